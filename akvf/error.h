#pragma once
// Typed errors. Library code never prints or exits; it throws one of these with
// a message a user can act on, and the programs map them to exit codes.
#include <stdexcept>
#include <string>

namespace akvf {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file could not be read or is malformed. The message names the file and,
// where there is one, the line: "line 12 of cow.obj: face index 9001 out of
// range (3195 vertices)".
class InputError : public Error {
 public:
  InputError(const std::string& file, long line, const std::string& problem);
  explicit InputError(const std::string& message) : Error(message) {}
};

// The mesh was read but cannot be optimized (wrong topology, degenerate
// faces, ...).
class ValidationError : public Error {
 public:
  using Error::Error;
};

// An option has an invalid value or an unknown name.
class OptionsError : public Error {
 public:
  using Error::Error;
};

// A numerical method failed (a matrix that should be positive definite is
// not, a factorization ran out of memory, ...).
class NumericalError : public Error {
 public:
  using Error::Error;
};

// An output file could not be written.
class OutputError : public Error {
 public:
  using Error::Error;
};

// A number as messages print it: six significant digits, exponent where
// needed ("0.001", "1e-13"; std::to_string would print "0.000000").
std::string number_text(double value);

}  // namespace akvf
