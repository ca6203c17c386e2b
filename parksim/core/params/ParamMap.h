#pragma once
// Parameters of a planner or a controller chosen by name (a registered implementation, built in
// or a user's plugin), as the user wrote them: name -> value text. The command line
// (`--planner-param NAME=VALUE`), a sweep spec's `set:` axes (`planner.NAME`, `controller.NAME`)
// and Python keyword arguments all fill the same map; the implementation reads and validates
// its own entries and refuses a name it does not know, so a typo is an error, not a default.
//
// Values are canonical text: numbers in their shortest round-trip form (formatGeneral),
// booleans "true"/"false", anything else as written. Episode ids hash this text.

#include <map>
#include <string>

namespace parksim {

using ParamMap = std::map<std::string, std::string>;

}  // namespace parksim
