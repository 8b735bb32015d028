// Test helper: running a command line (the CLI, scripts) and collecting what it prints.
#pragma once

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

}  // namespace singlestrip::test
