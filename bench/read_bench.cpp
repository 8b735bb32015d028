// singlestrip_bench — the "read" section: read_mesh_file on generated files of each format.
//
// A torus grid of n triangles (n/2 vertices, float-valued coordinates) is written in each format
// by a child process, then read in another child (so neither the writer's nor an earlier read's
// memory counts): the median of `reps` reads after one untimed read that warms the page cache,
// MB/s of file bytes, and the peak memory the read added (ru_maxrss after minus before).
#include "read_bench.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace fs = std::filesystem;

namespace {

struct Grid {
    uint32_t nu = 0, nv = 0;
    float x(uint32_t i, uint32_t j, int k) const {
        const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
        const double r = 1 + 0.35 * std::cos(v);
        return static_cast<float>(k == 0 ? r * std::cos(u) : k == 1 ? r * std::sin(u) : 0.35 * std::sin(v));
    }
    uint32_t id(uint32_t i, uint32_t j) const { return (i % nu) * nv + (j % nv); }
    /// Calls f(a, b, c) for every triangle, two per grid cell.
    template <class F>
    void triangles(F f) const {
        for (uint32_t i = 0; i < nu; ++i)
            for (uint32_t j = 0; j < nv; ++j) {
                f(id(i, j), id(i + 1, j), id(i + 1, j + 1));
                f(id(i, j), id(i + 1, j + 1), id(i, j + 1));
            }
    }
};

/// Buffered output with shortest round-trip float text.
struct Out {
    std::ofstream o;
    std::string buf;
    explicit Out(const std::string& path) : o(path, std::ios::binary) {}
    ~Out() { o.write(buf.data(), static_cast<std::streamsize>(buf.size())); }
    void put(std::string_view s) {
        buf.append(s);
        if (buf.size() > (1 << 20)) {
            o.write(buf.data(), static_cast<std::streamsize>(buf.size()));
            buf.clear();
        }
    }
    template <class T>
    void num(T v) {
        char b[32];
        put(std::string_view(b, static_cast<std::size_t>(std::to_chars(b, b + sizeof b, v).ptr - b)));
    }
    template <class T>
    void raw(T v) {
        put(std::string_view(reinterpret_cast<const char*>(&v), sizeof v));
    }
};

void write_file(const std::string& path, const std::string& format, const Grid& g) {
    Out o(path);
    const uint64_t nv = uint64_t{g.nu} * g.nv, nf = 2 * nv;
    auto vertices = [&](auto each) {
        for (uint32_t i = 0; i < g.nu; ++i)
            for (uint32_t j = 0; j < g.nv; ++j) each(g.x(i, j, 0), g.x(i, j, 1), g.x(i, j, 2));
    };
    auto text_vertex = [&](const char* prefix) {
        return [&o, prefix](float x, float y, float z) {
            o.put(prefix);
            o.num(x), o.put(" "), o.num(y), o.put(" "), o.num(z), o.put("\n");
        };
    };
    if (format == "ply-float" || format == "ply-double-parent") {
        const bool ours = format == "ply-double-parent";  // what write_strip_mesh writes
        const char* t = ours ? "double" : "float";
        std::ostringstream h;
        h << "ply\nformat binary_little_endian 1.0\nelement vertex " << nv << "\nproperty " << t << " x\nproperty " << t << " y\nproperty "
          << t << " z\nelement face " << nf << "\nproperty list uchar " << (ours ? "uint" : "int") << " vertex_indices\n"
          << (ours ? "property uint parent\n" : "") << "end_header\n";
        o.put(h.str());
        vertices([&](float x, float y, float z) {
            if (ours)
                o.raw(double{x}), o.raw(double{y}), o.raw(double{z});
            else
                o.raw(x), o.raw(y), o.raw(z);
        });
        uint32_t f = 0;
        g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
            o.raw(uint8_t{3}), o.raw(a), o.raw(b), o.raw(c);
            if (ours) o.raw(f++);
        });
    } else if (format == "off") {
        o.put("OFF\n"), o.num(nv), o.put(" "), o.num(nf), o.put(" 0\n");
        vertices(text_vertex(""));
        g.triangles(
            [&](uint32_t a, uint32_t b, uint32_t c) { o.put("3 "), o.num(a), o.put(" "), o.num(b), o.put(" "), o.num(c), o.put("\n"); });
    } else if (format == "obj") {
        vertices(text_vertex("v "));
        g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
            o.put("f "), o.num(a + 1), o.put(" "), o.num(b + 1), o.put(" "), o.num(c + 1), o.put("\n");
        });
    } else if (format == "stl") {
        o.put(std::string(80, ' ')), o.raw(static_cast<uint32_t>(nf));
        std::vector<float> p(3 * nv);
        uint64_t k = 0;
        vertices([&](float x, float y, float z) { p[k++] = x, p[k++] = y, p[k++] = z; });
        g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
            for (int n = 0; n < 3; ++n) o.raw(0.f);
            for (uint32_t v : {a, b, c})
                for (int n = 0; n < 3; ++n) o.raw(p[3 * v + n]);
            o.raw(uint16_t{0});
        });
    }
}

struct Result {
    int ok = 0;
    double seconds = 0, cpu = 0, mb = 0, peak_mb = 0;
    uint64_t triangles = 0;
    char message[200] = {};
};

double cpu_seconds() {
    rusage r{};
    getrusage(RUSAGE_SELF, &r);
    return static_cast<double>(r.ru_utime.tv_sec + r.ru_stime.tv_sec) + 1e-6 * static_cast<double>(r.ru_utime.tv_usec + r.ru_stime.tv_usec);
}

double max_rss_mb() {
    rusage r{};
    getrusage(RUSAGE_SELF, &r);
    return r.ru_maxrss / 1024.0;
}

/// Runs f in a forked child and returns the Result it wrote to a pipe.
template <class F>
Result in_child(F f) {
    int fd[2];
    if (pipe(fd) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        Result r = f();
        (void)!write(fd[1], &r, sizeof r);
        _exit(0);
    }
    close(fd[1]);
    Result r;
    if (read(fd[0], &r, sizeof r) != sizeof r) r.ok = 0;
    close(fd[0]);
    waitpid(pid, nullptr, 0);
    return r;
}

Result measure(const std::string& path, const std::string& format, int reps) {
    return in_child([&] {
        Result r;
        singlestrip::ReadOptions o;
        o.format = format;
        try {
            const double before = max_rss_mb();
            r.triangles = singlestrip::read_mesh_file(path, o).triangles.size();  // warms the page cache; counts the peak
            r.peak_mb = max_rss_mb() - before;
            std::vector<double> t, cpu;
            for (int i = 0; i < reps; ++i) {
                const auto t0 = std::chrono::steady_clock::now();
                const double c0 = cpu_seconds();
                (void)singlestrip::read_mesh_file(path, o);
                cpu.push_back(cpu_seconds() - c0);
                t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            }
            std::sort(t.begin(), t.end());
            std::sort(cpu.begin(), cpu.end());
            r.seconds = t[t.size() / 2];
            r.cpu = cpu[cpu.size() / 2];
            r.mb = static_cast<double>(fs::file_size(path)) / 1e6;
            r.ok = 1;
        } catch (const std::exception& e) {
            std::snprintf(r.message, sizeof r.message, "%s", e.what());
        }
        return r;
    });
}

}  // namespace

std::string read_section(const std::string& tmp, bool quick) {
    struct Case {
        const char* format;  // as written
        const char* read_as;
        const char* ext;
        const char* label;
    };
    const Case cases[] = {
        {"ply-float", "ply", ".ply", "binary PLY, float x y z, list uchar int"},
        {"ply-double-parent", "ply", ".ply", "binary PLY as written by singlestrip (double, list uchar uint, uint parent)"},
        {"off", "off", ".off", "ASCII OFF"},
        {"obj", "obj", ".obj", "OBJ"},
        {"stl", "stl", ".stl", "binary STL (corners welded)"}};
    std::vector<uint64_t> sizes = {1000000};
    if (!quick) sizes.push_back(10000000);
    std::ostringstream md;
    // CPU time (user + system) beside the wall time: on a shared machine the wall time also
    // counts the time other processes held the core.
    md << "| file | triangles | MB | read, wall (median) | MB/s | read, CPU (median) | MB per CPU s | peak memory added by the read | "
          "bytes per "
          "triangle |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const uint64_t n : sizes) {
        Grid g;
        g.nu = static_cast<uint32_t>(std::lround(std::sqrt(n / 2.0)));
        g.nv = static_cast<uint32_t>(n / 2 / g.nu);
        for (const Case& c : cases) {
            const std::string path = (fs::path(tmp) / (std::string("read-") + c.format + c.ext)).string();
            in_child([&] {
                write_file(path, c.format, g);
                return Result{};
            });
            const Result r = measure(path, c.read_as, quick ? 3 : 5);
            std::error_code ec;
            fs::remove(path, ec);
            char line[400];
            if (!r.ok) {
                std::snprintf(line, sizeof line, "| %s | %llu | – | failed: %s | | | | | |\n", c.label,
                              static_cast<unsigned long long>(2ull * g.nu * g.nv), r.message);
            } else {
                std::snprintf(line, sizeof line, "| %s | %llu | %.0f | %.3f s | %.0f | %.3f s | %.0f | %.0f MB | %.0f |\n", c.label,
                              static_cast<unsigned long long>(r.triangles), r.mb, r.seconds, r.mb / r.seconds, r.cpu, r.mb / r.cpu,
                              r.peak_mb, r.peak_mb * 1048576.0 / static_cast<double>(r.triangles));
            }
            md << line;
        }
    }
    return md.str();
}
