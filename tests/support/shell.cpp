#include "shell.hpp"

#include <sys/wait.h>
#include <unistd.h>

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

ShellRun run_program(const std::string& exe, const std::string& args) {
    return run_shell(shell_quote(exe) + " " + args + " 2>&1");
}

ScratchDir::ScratchDir(const std::string& tag)
    : dir(std::filesystem::temp_directory_path() / ("singlestrip-test-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
}

std::string ScratchDir::operator/(const std::string& name) const {
    return (dir / name).string();
}

}  // namespace singlestrip::test
