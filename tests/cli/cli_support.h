// Running programs from the CLI tests: a command line in a folder, with its exit code and output captured.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_support {

namespace fs = std::filesystem;

struct CliRun {
    int exit_code = -1; // -1: ended by a signal
    std::string out, err;
};

inline std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// Runs the shell command line `command` in `dir` with no standard input, capturing stdout and stderr.
inline CliRun run_in(const std::string& command, const fs::path& dir) {
    fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    // Appends, not a chain of operator+ (GCC 12 warns falsely about those: -Wrestrict, its bug 105329).
    std::string cmd = "cd '";
    cmd.append(dir.string()).append("' && ").append(command);
    cmd.append(" > '").append(out.string()).append("' 2> '").append(err.string()).append("' < /dev/null");
    int status = std::system(cmd.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_bytes(out);
    r.err = read_bytes(err);
    return r;
}

// Runs illum with the arguments (a shell-quoted string).
inline CliRun illum(const std::string& args, const fs::path& dir) {
    std::string command = "'";
    command.append(ILLUM_CLI_PATH).append("' ").append(args);
    return run_in(command, dir);
}


// A fresh, empty folder for the running test: <tmp>/illum-<prefix>-<pid>-<test name>.
inline fs::path fresh_test_folder(const std::string& prefix) {
    fs::path dir = fs::temp_directory_path() /
                   ("illum-" + prefix + "-" + std::to_string(::getpid()) + "-" +
                    testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace cli_support
