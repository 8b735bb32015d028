// File names: case-insensitive extensions and format names (io.hpp).
#include <algorithm>
#include <filesystem>
#include <string>

#include "singlestrip/io.hpp"

namespace singlestrip {

std::string ascii_lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c); });
    return s;
}

std::string lower_extension(const std::string& path) {
    return ascii_lower(std::filesystem::path(path).extension().string());
}

}  // namespace singlestrip
