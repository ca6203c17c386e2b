#pragma once
// The parameters a planner or a controller declares (OMPL's ParamSet): each binds a name to a
// field of the implementation's own Def struct, so the Def's initializer stays the one place
// that states the default, and a ParamMap from a command line, a sweep axis or Python is
// applied to it with the same checks everywhere.
//
//   TrackingDef def;                         // defaults from the initializers
//   ParamSet params("controller tracking");
//   params.add("bandwidth_radps", &def.bandwidth_radps, "error decay rate, rad/s", 0.0, 1e3);
//   params.apply(user_params);               // throws Error on an unknown name or a bad value
//
// A ParamSet refers to the fields it binds: use it while they live.

#include <functional>
#include <string>
#include <vector>

#include "parksim/core/params/ParamMap.h"

namespace parksim {

/// One declared parameter, as help texts and the registry list it.
struct ParamInfo {
  std::string name;
  std::string default_text;  ///< the bound field's value when declared, canonical text
  std::string description;   ///< what it does, with its unit
  std::string range;         ///< accepted values, e.g. "[0, 1]", "true|false", "a|b"
};

class ParamSet {
 public:
  /// `owner` names the implementation in messages ("planner rrt-star").
  explicit ParamSet(std::string owner);

  /// A real number in [min, max] (NaN never accepted).
  void add(const std::string& name, double* field, const std::string& description, double min,
           double max);
  /// An integer in [min, max].
  void add(const std::string& name, int* field, const std::string& description, int min, int max);
  /// true or false.
  void add(const std::string& name, bool* field, const std::string& description);
  /// One of `choices`.
  void add(const std::string& name, std::string* field, const std::string& description,
           const std::vector<std::string>& choices);
  /// A comma-separated list of 1..max_count reals, each in [min, max] ("0.02,0.08").
  void add(const std::string& name, std::vector<double>* field, const std::string& description,
           double min, double max, int max_count);

  /// Sets every named field from `params`. Throws Error "OWNER: unknown parameter 'x' (known:
  /// a, b)" or "OWNER: parameter a: expected ..., got 'v'"; fields before the bad entry may have
  /// been set, so apply to a copy that is dropped on error.
  void apply(const ParamMap& params) const;

  /// Every declared parameter, in declaration order.
  const std::vector<ParamInfo>& infos() const { return infos_; }
  const std::string& owner() const { return owner_; }

 private:
  struct Binding {
    std::function<void(const std::string&)> set;  // throws the "expected ..." text
  };
  void declare(ParamInfo info, std::function<void(const std::string&)> set);

  std::string owner_;
  std::vector<ParamInfo> infos_;
  std::vector<Binding> bindings_;
};

/// The canonical text of a parameter value (ParamMap.h): numbers parsed and written back in
/// their shortest round-trip form, "true"/"false" as they are, anything else unchanged.
std::string canonicalParamText(const std::string& text);

/// "NAME=VALUE" split at the first '='; throws Error naming `what` when there is none or NAME
/// is empty.
std::pair<std::string, std::string> splitParamAssignment(const std::string& text,
                                                         const std::string& what);

}  // namespace parksim
