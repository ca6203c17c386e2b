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

/// Code a user brought (a plugin's, a Python object's or a command's planner or controller)
/// failed: it threw, returned something unusable (NaN, a malformed plan, commands out of range),
/// ran out of its time, or its process died. Not an Error: the input was fine, and an episode
/// ends in planner_error or controller_error for it (pipeline/Verdict.h) while a sweep goes on.
class UserCodeError : public std::runtime_error {
 public:
  enum class Component { kPlanner, kController };
  UserCodeError(Component component, const std::string& what)
      : std::runtime_error(what), component_(component) {}
  Component component() const { return component_; }

 private:
  Component component_;
};

}  // namespace parksim
