#pragma once
// The one exception type parksim throws for bad input and misconfiguration. Its message is a
// single line meant for the user ("file:line: field: what is wrong"). Expected outcomes, such
// as an unsolved plan, are status values instead.

#include <stdexcept>
#include <string>

namespace parksim {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The machine lacks what a request needs (no OpenGL context can be made, a font is not
/// installed): not the input's fault. The command line exits with 3 for it rather than 2.
class EnvironmentError : public Error {
 public:
  using Error::Error;
};

}  // namespace parksim
