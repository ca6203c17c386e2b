#include "parksim/usercode/ComponentCheck.h"

#include <memory>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

using Kind = ComponentParams::Kind;

const char* kindName(Kind kind) { return kind == Kind::kPlanner ? "planner" : "controller"; }

UserCodeWatch::Phase phaseOf(Kind kind) {
  return kind == Kind::kPlanner ? UserCodeWatch::Phase::kPlanner
                                : UserCodeWatch::Phase::kController;
}

// Whose code its constructor is: a plugin's, run where a crash cannot end parksim; parksim's
// own or a command's; or a Python object's (user code, but made here).
struct Origin {
  bool plugin = false;
  bool trusted = false;
};

template <class Info>
Origin originOf(const Info& info) {
  return {!info.plugin.empty() && !info.own_process, info.trusted || info.own_process};
}

// Throws the registry's Error on an unknown name (before anything is made).
Origin originOf(const Components& components, const ComponentParams& c) {
  return c.kind == Kind::kPlanner ? originOf(components.planners.find(c.name).info)
                                  : originOf(components.controllers.find(c.name).info);
}

void make(const Components& components, const ComponentParams& c) {
  if (c.kind == Kind::kPlanner) {
    (void)components.planners.make(c.name, c.params);
  } else {
    (void)components.controllers.make(c.name, c.params);
  }
}

// The watch (if any) in c's phase while it lives, back in parksim's after, thrown or not.
class InComponent {
 public:
  InComponent(UserCodeWatch* watch, const ComponentParams& c) : watch_(watch) {
    if (watch_ != nullptr) watch_->enter(phaseOf(c.kind), c.name);
  }
  ~InComponent() {
    if (watch_ != nullptr) watch_->enter(UserCodeWatch::Phase::kParksim, "");
  }
  InComponent(const InComponent&) = delete;
  InComponent& operator=(const InComponent&) = delete;

 private:
  UserCodeWatch* watch_;
};

// A worker's answer: '+' made, or '-' and the one-line error.
constexpr char kMade = '+';
constexpr char kRefused = '-';

}  // namespace

std::optional<ComponentRefusal> firstRefusedComponent(const Components& components,
                                                      const std::vector<ComponentParams>& list,
                                                      const ComponentCheckDef& def) {
  // A plugin's constructors, task i making list[i]: one process for the list, not one each.
  const WatchedWorker::Work work = [&](std::uint64_t task, UserCodeWatch& watch) -> std::string {
    const ComponentParams& c = list.at(task);
    try {
      const InComponent in(&watch, c);
      make(components, c);
    } catch (const Error& e) {
      return kRefused + std::string(e.what());
    } catch (const std::exception& e) {
      return kRefused + std::string(kindName(c.kind)) + " " + c.name +
             " threw while being made: " + e.what();
    }
    return std::string(1, kMade);
  };
  std::unique_ptr<WatchedWorker> worker;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ComponentParams& c = list[i];
    try {
      const Origin origin = originOf(components, c);
      if (!origin.plugin || !def.isolate || def.watch != nullptr) {
        const InComponent in(origin.trusted ? nullptr : def.watch, c);
        make(components, c);
        continue;
      }
    } catch (const Error& e) {
      return ComponentRefusal{i, e.what()};
    }
    if (!worker) worker = std::make_unique<WatchedWorker>(work, def.limits, def.hooks);
    worker->start(i);
    const WorkerResult r = worker->wait();
    if (r.answer && r.answer->size() >= 1 && r.answer->front() == kMade) continue;
    if (r.answer) return ComponentRefusal{i, r.answer->substr(1)};
    if (r.user_failure) {
      return ComponentRefusal{
          i, std::string(r.user_failure->what()) + " while being made to check its parameters"};
    }
    return ComponentRefusal{i, std::string(kindName(c.kind)) + " " + c.name +
                                   ", made to check its parameters: " + r.failure};
  }
  return std::nullopt;
}

void checkComponents(const Components& components, const std::vector<ComponentParams>& list,
                     const ComponentCheckDef& def) {
  if (const std::optional<ComponentRefusal> refused =
          firstRefusedComponent(components, list, def)) {
    throw Error(refused->message);
  }
}

}  // namespace parksim
