#include "cgal_data.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>

namespace fs = std::filesystem;

namespace singlestrip::test {
namespace {

constexpr const char* kTarball = "/usr/share/doc/libcgal-dev/data.tar.gz";

std::string find_in(const fs::path& dir, const std::string& name) {
    for (const fs::path& p : {dir / name, dir / "meshes" / name, dir / "data" / "meshes" / name}) {
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) return p.string();
    }
    return {};
}

/// Directory the tarball is extracted into, or "" if extraction is impossible.
fs::path extracted_dir() {
    static fs::path dir;
    static std::once_flag once;
    std::call_once(once, [] {
        std::error_code ec;
        if (!fs::is_regular_file(kTarball, ec)) return;
        fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        fs::path base = ec ? fs::current_path() : exe.parent_path();
        fs::path target = base / "cgal-data";
        if (fs::is_directory(target / "data" / "meshes", ec)) {
            dir = target;
            return;
        }
        // Parallel test processes may race: each extracts privately and renames; losers clean up.
        fs::path tmp = base / ("cgal-data.tmp-" + std::to_string(::getpid()));
        fs::remove_all(tmp, ec);
        fs::create_directories(tmp, ec);
        const std::string cmd = "tar xzf '" + std::string(kTarball) + "' -C '" + tmp.string() + "' data/meshes >/dev/null 2>&1";
        if (std::system(cmd.c_str()) != 0) {
            fs::remove_all(tmp, ec);
            return;
        }
        fs::rename(tmp, target, ec);
        if (ec) fs::remove_all(tmp, ec);
        if (fs::is_directory(target / "data" / "meshes", ec)) dir = target;
    });
    return dir;
}

}  // namespace

std::string cgal_mesh_path(const std::string& name) {
    if (const char* env = std::getenv("SINGLESTRIP_CGAL_DATA"); env && *env) return find_in(env, name);
    fs::path dir = extracted_dir();
    return dir.empty() ? std::string() : find_in(dir, name);
}

const std::vector<KnownTopology>& known_topologies() {
    static const std::vector<KnownTopology> meshes = {{"fandisk.off", 0, 0},
                                                      {"head.off", 0, 3},
                                                      {"eight.off", 2, 0},
                                                      {"cheese.off", 133, 0},
                                                      {"elephant-with-holes.off", 3, 106},
                                                      {"double-torus-3-holes.off", 2, 3}};
    return meshes;
}

}  // namespace singlestrip::test
