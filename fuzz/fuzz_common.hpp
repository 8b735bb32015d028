// singlestrip fuzzing — helpers shared by the libFuzzer targets.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace singlestrip::fuzzcheck {

/// The readers take a path: fuzz bytes go to a per-process file in /dev/shm (RAM), rewritten
/// on every input.
inline std::string write_temp(const uint8_t* data, size_t size, const std::string& ext) {
    static const std::string dir = [] {
        const char* d = std::getenv("SINGLESTRIP_FUZZ_TMP");
        return std::string(d ? d : (access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp"));
    }();
    std::string path = dir + "/singlestrip_fuzz_" + std::to_string(getpid()) + ext;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        std::perror(path.c_str());
        std::abort();
    }
    if (size && std::fwrite(data, 1, size, f) != size) {
        std::perror(path.c_str());
        std::abort();
    }
    std::fclose(f);
    return path;
}

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "\n*** singlestrip fuzz finding ***\n%s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace singlestrip::fuzzcheck
