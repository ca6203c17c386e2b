#pragma once
// Components chosen by name: planners (planner/base/PlannerRegistry.h) and controllers
// (sim/control/Controller.h), parksim's own and those plugins add. One registry type for both,
// so names, errors and trust follow the same rules.
//
// An Entry is a struct with `info` (holding `name`, `params`, `runs_user_code`, `trusted` and
// `plugin`) and
// `make`, a factory taking a ParamMap; it names its kind in `Entry::kKind` ("planner").

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/core/params/ParamSet.h"

namespace parksim {

/// True when `name` may name a component: 1 to 64 ASCII letters, digits, '-', '_' or '.'.
inline bool isComponentName(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
  });
}

template <class Entry>
class ComponentRegistry {
 public:
  /// Adds `entry`, marked as registered by `plugin` ("" for parksim's own); it is trusted
  /// (info.trusted) when no plugin registers it and it runs no user code. Throws Error when the
  /// name is not a component name, there is no factory, or the name is taken.
  void add(Entry entry, const std::string& plugin = "") {
    const std::string& name = entry.info.name;
    if (!isComponentName(name)) {
      throw Error(std::string(Entry::kKind) + " name '" + escapeText(name) +
                  "': 1 to 64 letters, digits, '-', '_' or '.'");
    }
    if (!entry.make) throw Error(std::string(Entry::kKind) + " " + name + ": no factory");
    if (const Entry* known = tryFind(name)) {
      throw Error(std::string(Entry::kKind) + " " + name + " is registered twice (" +
                  origin(known->info.plugin) + ", then " + origin(plugin) + ")");
    }
    entry.info.plugin = plugin;
    entry.info.trusted = plugin.empty() && !entry.info.runs_user_code;
    entries_.push_back(std::move(entry));
  }

  /// The entry of `name`, or null.
  const Entry* tryFind(const std::string& name) const {
    for (const Entry& e : entries_) {
      if (e.info.name == name) return &e;
    }
    return nullptr;
  }

  /// The entry of `name`; throws Error "unknown planner 'x' (expected one of a, b)".
  const Entry& find(const std::string& name) const {
    if (const Entry* e = tryFind(name)) return *e;
    throw Error("unknown " + std::string(Entry::kKind) + " '" + escapeText(name) +
                "' (expected one of " + joinNames(names()) + ")");
  }

  /// Every name, in registration order (parksim's own first).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.info.name);
    return out;
  }

  const std::vector<Entry>& entries() const { return entries_; }

  /// A component `name` with `params` applied; throws Error on an unknown name or parameter.
  auto make(const std::string& name, const ParamMap& params) const {
    auto made = find(name).make(params);
    if (!made) throw Error(std::string(Entry::kKind) + " " + name + ": its factory made nothing");
    return made;
  }

 private:
  static std::string origin(const std::string& plugin) {
    return plugin.empty() ? std::string("built in") : "by plugin " + plugin;
  }

  std::vector<Entry> entries_;
};

/// The parameters `bind` declares on a copy of `def` (their defaults are def's values).
template <class Def>
std::vector<ParamInfo> declaredParams(const std::string& owner, Def def,
                                      void (*bind)(Def&, ParamSet&)) {
  ParamSet set(owner);
  bind(def, set);
  return set.infos();
}

/// A factory making Impl(d) as Base, where d is `def` with a ParamMap applied through `bind`:
/// the Def's initializers are the defaults, and one binding lists and applies the parameters.
template <class Base, class Impl, class Def>
auto boundFactory(const std::string& owner, Def def, void (*bind)(Def&, ParamSet&)) {
  return [owner, def, bind](const ParamMap& params) {
    Def d = def;
    ParamSet set(owner);
    bind(d, set);
    set.apply(params);
    return std::unique_ptr<Base>(std::make_unique<Impl>(d));
  };
}

}  // namespace parksim
