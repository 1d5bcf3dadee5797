// `illum verify`: the radiometry of the course as checks a user runs in a minute (docs/verification.md,
// "illum verify"): radiometry_checks.h (disk irradiance, the rule of five, the closed furnace, radiance
// invariance, the Lambertian plane under a uniform sky), light_checks.h (every light's power by sample_le
// and power()), sh_checks.h (SH and brute-force irradiance) and bsdf_checks.h (the audits of every model).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "illum/analysis/verify_check.h"

namespace illum {

struct VerifyReport {
    std::vector<VerifyCheck> checks;
    double seconds = 0;
    int failed() const;
};

// The groups, in the order they run: radiometry, lights, envmap, bsdf.
const std::vector<std::string>& verify_groups();

// Runs the groups named in `groups` (all when empty); `on_check` sees each check as it is judged.
VerifyReport run_verify(const VerifyOptions& options, const std::vector<std::string>& groups = {},
                        const std::function<void(const VerifyCheck&)>& on_check = {});

// One line: PASS/FAIL, the check, its closed form, expected, measured ± standard error, tolerance.
std::string verify_line(const VerifyCheck& check);
// {"passed": bool, "failures": n, "seconds": t, "checks": [{"group", "name", "closed_form", "expected",
//  "measured", "standard_error", "tolerance", "relation" ("=" or "<="), "passed", "detail"}, ...]}
std::string verify_json(const VerifyReport& report);

} // namespace illum
