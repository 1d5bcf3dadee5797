// illum: the command line. `illum render` with no scene renders the built-in Cornell box.
#include <cstdio>
#include <exception>

#include <fmt/core.h>

#include "commands.h"
#include "illum/util/error.h"
#include "mpi_run.h"

namespace {

// Prints an error and returns `code`; in a job of several ranks, where the others may be waiting for this
// one, names the rank and ends the whole job with that code.
int fail(const char* what, int code) {
    using illum::cli::MpiRun;
    if (MpiRun::size() <= 1) {
        fmt::print(stderr, "error: {}\n", what);
        return code;
    }
    fmt::print(stderr, "error: rank {} of {}: {}\n", MpiRun::rank(), MpiRun::size(), what);
    MpiRun::abort(code);
}

} // namespace

int main(int argc, char** argv) {
    illum::cli::MpiRun mpi(&argc, &argv); // under mpirun: this process is one rank of a job
    const bool lead = illum::cli::MpiRun::rank() == 0;
    CLI::App app{"illum: a physically based renderer and reflectance toolkit"};
    // The instruction-set level this build was compiled for (CMakeLists.txt: the launcher picks between the
    // x86-64 and x86-64-v3 builds).
    app.set_version_flag("--version", "illum " ILLUM_VERSION " (" ILLUM_ISA_LEVEL ")");
    app.require_subcommand(0, 1);
    illum::cli::add_render_command(app);
    illum::cli::add_bench_command(app);
    illum::cli::add_brdf_command(app);
    illum::cli::add_diff_command(app);
    illum::cli::add_info_command(app);
    illum::cli::add_envmap_command(app);
    illum::cli::add_photons_command(app);
    illum::cli::add_verify_command(app);
    try {
        app.parse(argc, argv);
        if (app.get_subcommands().empty()) {
            // No subcommand: render the built-in scene, as `illum render` does.
            return app.get_subcommand("render")->parse(std::vector<std::string>{}), 0;
        }
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code(); // a command that reports its own failure (a failed audit)
    } catch (const CLI::ParseError& e) {
        if (lead) fmt::print(stderr, "error: {}\n", e.what()); // every rank has the same arguments
        return 2;
    } catch (const illum::cli::ReportedFailure&) {
        return 2;
    } catch (const illum::Error& e) {
        return fail(e.what(), 2);
    } catch (const std::exception& e) {
        return fail(e.what(), 1);
    }
    return 0;
}
