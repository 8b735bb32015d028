// The batch progress bar; see progress.hpp.
#include "app/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace singlestrip::app {
namespace {

void draw(const BatchProgress& p) {
    constexpr int kWidth = 30;
    const int filled = p.total ? static_cast<int>(kWidth * p.done / p.total) : kWidth;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(kWidth - filled), '.');
    const std::string name = p.last.size() > 40 ? "..." + p.last.substr(p.last.size() - 37) : p.last;
    const std::string failed = p.failed ? " (" + std::to_string(p.failed) + " failed)" : std::string();
    std::fprintf(stderr, "\r[%s] %zu/%zu%s  %-40s", bar.c_str(), p.done, p.total, failed.c_str(), name.c_str());
    if (p.done == p.total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

}  // namespace

ProgressBar::ProgressBar() : terminal_(isatty(fileno(stderr)) != 0) {}

BatchProgressFn ProgressBar::callback() const {
    if (!terminal_) return {};
    return draw;
}

}  // namespace singlestrip::app
