#include "app/Validators.h"

#include <string>

#include "parksim/core/NumberFormat.h"

namespace parksim::app {

namespace {

CLI::Validator numberAtLeast(bool strict, const char* wanted, const char* tag) {
  return CLI::Validator(
      [strict, wanted](std::string& text) -> std::string {
        double value = 0.0;
        if (parseDouble(text, value) && (strict ? value > 0.0 : value >= 0.0)) return "";
        return std::string("must be ") + wanted + ", got " + text;
      },
      tag);
}

}  // namespace

CLI::Validator positiveNumber() { return numberAtLeast(true, "a positive number", "POSITIVE"); }

CLI::Validator nonNegativeNumber() {
  return numberAtLeast(false, "zero or a positive number", "NONNEGATIVE");
}

}  // namespace parksim::app
