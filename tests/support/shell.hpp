// Test helper: running a command line (the CLI, scripts) and collecting what it prints.
#pragma once

#include <filesystem>
#include <string>

namespace singlestrip::test {

struct ShellRun {
    int code = -1;    ///< exit status, -1 when the command did not exit normally
    std::string out;  ///< standard output (with stderr when the command line redirects it)
};

/// Runs `cmd` through /bin/sh (popen) and reads its standard output to the end.
ShellRun run_shell(const std::string& cmd);

/// `s` in single quotes for the shell (test paths hold no single quote).
std::string shell_quote(const std::string& s);

/// Runs the program `exe` with `args` (shell-quoted where needed), standard error merged into `out`.
ShellRun run_program(const std::string& exe, const std::string& args);

/// A fresh empty directory <temp>/singlestrip-test-<tag>-<pid> (the pid keeps parallel test
/// processes apart), removed with its contents when the object goes.
struct ScratchDir {
    explicit ScratchDir(const std::string& tag);
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    /// The path of `name` inside the directory.
    std::string operator/(const std::string& name) const;
    std::filesystem::path dir;
};

#ifdef SINGLESTRIP_SOURCE_DIR
/// The path of tests/data/<name> in the source tree (test executables define the source dir).
inline std::string test_data(const std::string& name) {
    return std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + name;
}
#endif

}  // namespace singlestrip::test
