// singlestrip — error types.
//
// Every failure the library reports is a typed exception derived from singlestrip::Error. The
// programs map each type to one documented exit code (src/app/exit_codes.hpp, README "Exit codes").
#pragma once

#include <stdexcept>
#include <string>

namespace singlestrip {

/// Base of all singlestrip errors.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The input (file or arrays) is not a valid mesh for stripification. The message names the
/// file (when there is one), the element (vertex / face / edge / line) and the problem.
class InputError : public Error {
public:
    using Error::Error;
};

/// The mesh is valid but a requested option cannot be satisfied (out-of-range seed face,
/// source/target vertex, constraint edge that is not a mesh edge, constraints that cut the surface).
class RequestError : public Error {
public:
    using Error::Error;
};

/// Writing an output file failed.
class OutputError : public Error {
public:
    using Error::Error;
};

/// An internal invariant was broken (a bug in singlestrip). Raised instead of looping or
/// producing a wrong strip.
class InternalError : public Error {
public:
    using Error::Error;
};

}  // namespace singlestrip
