#include "shell.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace singlestrip::test {

ShellRun run_shell(const std::string& cmd) {
    ShellRun r;
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    for (size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) r.out.append(buf.data(), n);
    const int status = ::pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string shell_quote(const std::string& s) {
    return "'" + s + "'";
}

}  // namespace singlestrip::test
