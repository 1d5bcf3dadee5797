// `illum verify`: the course's radiometry as checks of this build (analysis/verify.h), each printed with
// its closed form, the measured value, its standard error and PASS or FAIL; exits 1 when any fails.
#include <cstdio>
#include <memory>

#include <fmt/core.h>

#include "commands.h"
#include "illum/analysis/verify.h"

namespace illum::cli {

namespace {

struct VerifyArgs {
    bool json = false;
    std::vector<std::string> groups;
    VerifyOptions options;
};

} // namespace

void add_verify_command(CLI::App& app) {
    auto a = std::make_shared<VerifyArgs>();
    CLI::App* c = app.add_subcommand(
        "verify",
        "Check this build's radiometry against closed forms: disk irradiance, the rule of five, closed "
        "furnaces, radiance invariance, a Lambertian plane, light power, SH irradiance, BSDF audits "
        "(about 10 s); exits 1 on a failure");
    c->add_flag("--json", a->json, "print the checks as JSON instead of text");
    c->add_option("--only", a->groups,
                  "run only these groups: radiometry, lights, envmap, bsdf (repeatable)");
    c->add_option("--threads", a->options.threads, "render threads (default: all)")
        ->check(positive_integer());
    c->add_option("--seed", a->options.seed, "seed of every estimate (the tolerances hold for any)");
    c->callback([a] {
        std::string group;
        auto print = [&](const VerifyCheck& k) {
            if (a->json) return;
            if (k.group != group) fmt::print("\n== {} ==\n", group = k.group);
            fmt::print("{}\n", verify_line(k));
            std::fflush(stdout);
        };
        VerifyReport r = run_verify(a->options, a->groups, print);
        if (a->json)
            fmt::print("{}\n", verify_json(r));
        else
            fmt::print("\n{} checks, {} failed, {:.1f} s\n", r.checks.size(), r.failed(), r.seconds);
        std::fflush(stdout);
        if (r.failed() > 0) throw CLI::RuntimeError(1);
    });
}

} // namespace illum::cli
