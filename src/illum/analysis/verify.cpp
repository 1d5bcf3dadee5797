#include "illum/analysis/verify.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "illum/analysis/bsdf_checks.h"
#include "illum/analysis/light_checks.h"
#include "illum/analysis/radiometry_checks.h"
#include "illum/analysis/sh_checks.h"
#include "illum/util/error.h"

namespace illum {

int VerifyReport::failed() const {
    return int(std::count_if(checks.begin(), checks.end(), [](const VerifyCheck& c) { return !c.passed; }));
}

const std::vector<std::string>& verify_groups() {
    static const std::vector<std::string> g = {"radiometry", "lights", "envmap", "bsdf"};
    return g;
}

VerifyReport run_verify(const VerifyOptions& o, const std::vector<std::string>& groups,
                        const std::function<void(const VerifyCheck&)>& on_check) {
    for (const std::string& g : groups)
        if (std::find(verify_groups().begin(), verify_groups().end(), g) == verify_groups().end())
            throw Error("unknown check group \"" + g + "\" (radiometry, lights, envmap or bsdf)");
    auto wanted = [&](const char* g) {
        return groups.empty() || std::find(groups.begin(), groups.end(), g) != groups.end();
    };
    auto start = std::chrono::steady_clock::now();
    VerifyReport report;
    auto add = [&](VerifyCheck c) {
        if (on_check) on_check(c);
        report.checks.push_back(std::move(c));
    };
    auto add_all = [&](std::vector<VerifyCheck> cs) {
        for (VerifyCheck& c : cs) add(std::move(c));
    };
    if (wanted("radiometry")) {
        add_all(check_disk_irradiance(o));
        add_all(check_rule_of_five(o));
        add(check_closed_furnace(0.5, 0.7, o));
        add(check_closed_furnace(0.8, 0.7, o));
        add_all(check_radiance_invariance(o));
        add(check_lambertian_plane(0.6, o));
    }
    if (wanted("lights")) add_all(check_light_powers(o));
    if (wanted("envmap")) add_all(check_sh_irradiance(o));
    if (wanted("bsdf")) add_all(check_bsdf_audits(o));
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

std::string verify_line(const VerifyCheck& c) {
    std::string figures =
        c.upper_bound
            ? fmt::format("bound {:.6g}  measured {:.6g} ± {:.2g}  (passes up to {:.6g})", c.expected,
                          c.measured, c.standard_error, c.expected + c.tolerance)
            : fmt::format("expected {:.6g}  measured {:.6g} ± {:.2g}  (|Δ| = {:.2g}, tolerance {:.2g})",
                          c.expected, c.measured, c.standard_error, std::abs(c.measured - c.expected),
                          c.tolerance);
    std::string line =
        fmt::format("{}  {:<74} {}\n      {}", c.passed ? "PASS" : "FAIL", c.name, c.closed_form, figures);
    if (!c.detail.empty()) line += "  " + c.detail;
    return line;
}

std::string verify_json(const VerifyReport& r) {
    nlohmann::json j;
    j["passed"] = r.failed() == 0;
    j["failures"] = r.failed();
    j["checks_run"] = r.checks.size();
    j["seconds"] = r.seconds;
    j["checks"] = nlohmann::json::array();
    for (const VerifyCheck& c : r.checks)
        j["checks"].push_back({{"group", c.group},
                               {"name", c.name},
                               {"closed_form", c.closed_form},
                               {"expected", c.expected},
                               {"measured", c.measured},
                               {"standard_error", c.standard_error},
                               {"tolerance", c.tolerance},
                               {"relation", c.upper_bound ? "<=" : "="},
                               {"passed", c.passed},
                               {"detail", c.detail}});
    return j.dump(1);
}

} // namespace illum
