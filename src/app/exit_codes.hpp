// The programs' exit codes (singlestrip, singlestrip-render; README, "Exit codes") and the one
// place that maps a library exception to its code and message. The library itself only throws
// typed errors (errors.hpp).
#pragma once

#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "singlestrip/errors.hpp"

namespace singlestrip::app {

enum ExitCode : int {
    kExitOk = 0,
    kExitUsage = 2,         ///< bad command line (unknown option, missing argument)
    kExitBadInput = 3,      ///< input file missing, unreadable, malformed or not a valid mesh
    kExitBadRequest = 4,    ///< a request that cannot be met (constraints, source/target, seed face)
    kExitVerifyFailed = 5,  ///< `singlestrip verify` found a violated property
    kExitInternal = 6,      ///< a broken internal invariant (a bug): reported, never a hang
    kExitOutput = 7,        ///< output file could not be written
};

/// The exit code of a failure: InputError 3, RequestError 4, OutputError 7, anything else 6.
inline int exit_code(const std::exception& e) noexcept {
    if (dynamic_cast<const InputError*>(&e)) return kExitBadInput;
    if (dynamic_cast<const RequestError*>(&e)) return kExitBadRequest;
    if (dynamic_cast<const OutputError*>(&e)) return kExitOutput;
    return kExitInternal;
}

/// The message of a failure as the programs print it after "error: ": a library error's own
/// message, "out of memory", or "internal: ..." for anything unexpected.
inline std::string error_message(const std::exception& e) {
    if (dynamic_cast<const Error*>(&e)) return e.what();
    if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
    return std::string("internal: ") + e.what();
}

/// Runs `body` (returning an exit code); an exception is printed as "singlestrip: error: ..." on
/// stderr and becomes its exit code.
template <class Body>
int run_reporting_errors(Body&& body) {
    try {
        return body();
    } catch (const std::exception& e) {
        std::cerr << "singlestrip: error: " << error_message(e) << '\n';
        return exit_code(e);
    }
}

}  // namespace singlestrip::app
