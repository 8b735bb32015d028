// singlestrip — error types and the CLI's exit codes.
//
// Every failure the library reports is a typed exception derived from singlestrip::Error.
// The CLI maps each type to one documented exit code (README, "Exit codes").
#pragma once

#include <stdexcept>
#include <string>

namespace singlestrip {

/// Exit codes of the `singlestrip` command line tool.
enum ExitCode : int {
    kExitOk = 0,
    kExitUsage = 2,         ///< bad command line (unknown option, missing argument)
    kExitBadInput = 3,      ///< input file missing, unreadable, malformed or not a valid mesh
    kExitBadRequest = 4,    ///< a request that cannot be met (constraints, source/target, seed face)
    kExitVerifyFailed = 5,  ///< `singlestrip verify` found a violated property
    kExitInternal = 6,      ///< a broken internal invariant (a bug): reported, never a hang
    kExitOutput = 7,        ///< output file could not be written
};

/// Base of all singlestrip errors.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    [[nodiscard]] virtual int exit_code() const noexcept { return kExitInternal; }
};

/// The input (file or arrays) is not a valid mesh for stripification. The message names the
/// file (when there is one), the element (vertex / face / edge / line) and the problem.
class InputError : public Error {
public:
    using Error::Error;
    [[nodiscard]] int exit_code() const noexcept override { return kExitBadInput; }
};

/// The mesh is valid but a requested option cannot be satisfied (out-of-range seed face,
/// source/target vertex, constraint edge that is not a mesh edge, constraints that cut the surface).
class RequestError : public Error {
public:
    using Error::Error;
    [[nodiscard]] int exit_code() const noexcept override { return kExitBadRequest; }
};

/// Writing an output file failed.
class OutputError : public Error {
public:
    using Error::Error;
    [[nodiscard]] int exit_code() const noexcept override { return kExitOutput; }
};

/// An internal invariant was broken (a bug in singlestrip). Raised instead of looping or
/// producing a wrong strip.
class InternalError : public Error {
public:
    using Error::Error;
    [[nodiscard]] int exit_code() const noexcept override { return kExitInternal; }
};

}  // namespace singlestrip
