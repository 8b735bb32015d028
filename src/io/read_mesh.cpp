// singlestrip — read_mesh_file: chooses the reader by format, loads the bytes once (read_common),
// and frees them before returning, so the peak is the bytes plus the soup.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "read_common.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {

TriangleSoup read_mesh_file(const std::string& path, const ReadOptions& options) {
    using namespace io_detail;
    const std::string named = ascii_lower(options.format);
    const std::string ext = named.empty() ? lower_extension(path) : "." + named;
    TriangleSoup (*reader)(const std::string&, std::string_view) = nullptr;
    if (ext == ".obj")
        reader = read_obj;
    else if (ext == ".off")
        reader = read_off;
    else if (ext == ".ply")
        reader = read_ply;
    else if (ext == ".stl")
        reader = read_stl;
    else if (!named.empty())
        fail(path, "unknown input format '" + options.format + "' (expected obj, off, ply or stl)");
    else
        fail(path, "unknown input format '" + ext + "' (expected .obj, .off, .ply or .stl, or a format named with --input-format)");

    Bytes bytes = load_bytes(path, options);
    const std::string_view d = bytes.view();
    if (std::all_of(d.begin(), d.end(), [](char c) { return is_space(c); })) fail(path, "empty file");
    TriangleSoup soup = reader(path, d);
    bytes.data.reset();  // before the soup is handed over: the peak is the bytes plus the soup
    return soup;
}

}  // namespace singlestrip
