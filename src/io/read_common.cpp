// singlestrip — shared parts of the mesh readers (see read_common.hpp).
#include "read_common.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "singlestrip/errors.hpp"

namespace singlestrip::io_detail {

void fail(const std::string& path, const std::string& what) {
    throw InputError(path + ": " + what);
}

namespace {

/// Closes a file descriptor on every path out of load_bytes.
struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

Bytes load_bytes(const std::string& path, const ReadOptions& options) {
    // Checked before opening: opening a device may itself do something (a tape rewinds).
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) fail(path, "no such file");
    if (std::filesystem::is_directory(status)) fail(path, "is a directory, not a mesh file");
    // A device (/dev/urandom) never ends; a pipe does, and is read like a file.
    if (!std::filesystem::is_regular_file(status) && !std::filesystem::is_fifo(status))
        fail(path, "is not a regular file or a pipe (devices and sockets are not read)");
    const Fd f{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (f.fd < 0) fail(path, std::string("cannot open file for reading (") + std::strerror(errno) + ")");
    struct stat st {};
    if (::fstat(f.fd, &st) != 0 || !(S_ISREG(st.st_mode) || S_ISFIFO(st.st_mode)))
        fail(path, "is not a regular file or a pipe (devices and sockets are not read)");
    const std::string too_large =
        "larger than the input limit of " + std::to_string(options.max_input_bytes) + " bytes (ReadOptions::max_input_bytes)";
    const std::uint64_t size = S_ISREG(st.st_mode) ? static_cast<std::uint64_t>(st.st_size) : 0;
    if (size > options.max_input_bytes) fail(path, too_large);
    // A regular file is read into a buffer of its size (it may still grow or shrink meanwhile);
    // a pipe has no size to ask for, so the buffer grows, refused as soon as it passes the limit.
    Bytes data;
    std::size_t capacity = static_cast<std::size_t>(size);
    data.data.reset(new char[capacity]);
    auto read_some = [&](char* into, std::size_t room) {
        for (;;) {
            const ssize_t n = ::read(f.fd, into, room);
            if (n >= 0) return static_cast<std::size_t>(n);
            if (errno != EINTR) fail(path, std::string("read error (") + std::strerror(errno) + ")");
        }
    };
    for (;;) {
        if (data.size < capacity) {
            const std::size_t n = read_some(data.data.get() + data.size, capacity - data.size);
            if (n == 0) break;
            data.size += n;
            continue;
        }
        // The buffer is full: a probe tells the end of a file from more data (a pipe, or a file
        // that grew), so that a complete file is never copied into a larger buffer.
        char probe[1 << 16];
        const std::size_t n = read_some(probe, sizeof probe);
        if (n == 0) break;
        if (data.size + n > options.max_input_bytes) fail(path, too_large);
        const std::uint64_t grown = std::max<std::uint64_t>({capacity * std::uint64_t{2}, data.size + n, sizeof probe});
        capacity = static_cast<std::size_t>(std::min<std::uint64_t>(grown, options.max_input_bytes));
        std::unique_ptr<char[]> bigger(new char[capacity]);
        std::memcpy(bigger.get(), data.data.get(), data.size);
        std::memcpy(bigger.get() + data.size, probe, n);
        data.data = std::move(bigger);
        data.size += n;
    }
    return data;
}

bool parse_out_of_range(const char* b, const char* e, double& v) {
    const std::string copy(b, e);
    v = std::strtod(copy.c_str(), nullptr);
    return std::isfinite(v);
}

std::string quoted(std::string_view t) {
    return "'" + std::string(t.substr(0, 40)) + (t.size() > 40 ? "...'" : "'");
}

std::string coordinate_problem(std::string_view t) {
    const std::string copy(t.substr(0, 400));
    char* end = nullptr;
    const double v = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() && *end == '\0' && !std::isfinite(v))
        return "has a non-finite coordinate " + quoted(t) + " (NaN, infinity or beyond the range of double)";
    return "cannot parse coordinate " + quoted(t);
}

void TextCursor::next_line() {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (!nl) {
        p = end;
        return;
    }
    p = static_cast<const char*>(nl) + 1;
    ++line;
}

TriangleSoup SoupBuilder::finish(const std::string& no_faces_detail) {
    if (soup.triangles.empty()) fail(path_, "no faces (" + no_faces_detail + ")");
    if (soup.points.size() >= 0xffffffffu) fail(path_, "too many vertices (more than 2^32-2)");
    return std::move(soup);
}

}  // namespace singlestrip::io_detail
