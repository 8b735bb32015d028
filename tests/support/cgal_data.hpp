// Test helper: locating the libcgal-demo meshes (data/meshes/*.off).
#pragma once

#include <string>

namespace singlestrip::test {

/// Path of the libcgal-demo mesh `name` (e.g. "fandisk.off"), or "" when unavailable (the test
/// should then GTEST_SKIP). Looks in $SINGLESTRIP_CGAL_DATA (a directory holding the file
/// directly, or meshes/NAME, or data/meshes/NAME); without the variable, extracts
/// /usr/share/doc/libcgal-dev/data.tar.gz once into "cgal-data/" next to the test executable
/// (atomically: extract to a temporary directory, then rename).
std::string cgal_mesh_path(const std::string& name);

}  // namespace singlestrip::test
