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

}  // namespace parksim
