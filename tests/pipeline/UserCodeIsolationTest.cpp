// User code that crashes or hangs ends its child process, not the caller, and becomes the
// failure of the component it was in (UserCodeIsolation.h).

#include "parksim/usercode/UserCodeIsolation.h"

#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/PluginLoader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace user_code_isolation_test {

using ::testing::HasSubstr;
using Phase = UserCodeWatch::Phase;

// Short limits: the hanging work below never ends, so only the limit ends it.
constexpr UserCodeLimits kShort{0.3, 0.3};

std::string userFailure(const std::function<std::string(UserCodeWatch&)>& work,
                        UserCodeError::Component* component = nullptr) {
  try {
    runIsolated(work, kShort);
  } catch (const UserCodeError& e) {
    if (component != nullptr) *component = e.component();
    return e.what();
  }
  return "";
}

// True when process `pid` no longer runs (/proc/PID/stat's state: gone or Z).
bool deadOrZombie(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const std::size_t paren = line.rfind(')');
  return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] == 'Z';
}

TEST(UserCodeIsolation, AnAnswerComesBack) {
  EXPECT_EQ(runIsolated([](UserCodeWatch&) { return std::string(100000, 'x'); }, kShort),
            std::string(100000, 'x'));
}

TEST(UserCodeIsolation, ACrashInUserCodeIsThatComponentsFailure) {
  UserCodeError::Component c{};
  EXPECT_EQ(userFailure(
                [](UserCodeWatch& w) -> std::string {
                  w.enter(Phase::kController, "wobbly");
                  std::raise(SIGSEGV);
                  return "";
                },
                &c),
            "controller wobbly crashed (SIGSEGV, Segmentation fault)");
  EXPECT_EQ(c, UserCodeError::Component::kController);
  EXPECT_EQ(userFailure(
                [](UserCodeWatch& w) -> std::string {
                  w.enter(Phase::kPlanner, "quitter");
                  std::exit(3);
                },
                &c),
            "planner quitter ended the process (exit status 3)");
  EXPECT_EQ(c, UserCodeError::Component::kPlanner);
}

TEST(UserCodeIsolation, AHangIsKilledAtItsLimitWithWhatItStarted) {
  EXPECT_EQ(userFailure([](UserCodeWatch& w) -> std::string {
              w.enter(Phase::kPlanner, "thinker");
              for (volatile bool forever = true; forever;) {
              }
              return "";
            }),
            "planner thinker ran past its time limit of 0.3 s (its process was killed)");
  // A controller that answers keeps its limit fresh; one that stops answering is killed.
  EXPECT_EQ(userFailure([](UserCodeWatch& w) -> std::string {
              for (int tick = 0; tick < 20; ++tick) {
                w.enter(Phase::kController, "slowpoke");
                usleep(20000);  // within the limit, every time
                w.enter(Phase::kParksim, "");
              }
              w.enter(Phase::kController, "slowpoke");
              pause();
              return "";
            }),
            "controller slowpoke gave no command within its time limit of 0.3 s (its process was "
            "killed)");
  // What user code started goes with it: a grandchild in the same process group.
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  (void)userFailure([&](UserCodeWatch& w) -> std::string {
    w.enter(Phase::kPlanner, "spawner");
    const pid_t grandchild = fork();
    if (grandchild == 0) {
      pause();
      _exit(0);
    }
    (void)!write(fds[1], &grandchild, sizeof grandchild);
    pause();
    return "";
  });
  pid_t grandchild = 0;
  ASSERT_EQ(read(fds[0], &grandchild, sizeof grandchild), static_cast<ssize_t>(sizeof grandchild));
  // Killed with its group: gone, or a zombie waiting for whoever adopted it to reap it (the
  // kernel may take a moment to end it after SIGKILL).
  for (int tries = 0; tries < 100 && !deadOrZombie(grandchild); ++tries) usleep(10000);
  EXPECT_TRUE(deadOrZombie(grandchild));
  close(fds[0]);
  close(fds[1]);
}

TEST(UserCodeIsolation, ParksimsOwnFailuresStayErrors) {
  try {
    runIsolated([](UserCodeWatch&) -> std::string { throw Error("world.yaml:3: bad"); }, kShort);
    FAIL();
  } catch (const UserCodeError&) {
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "world.yaml:3: bad");
  }
  try {
    runIsolated([](UserCodeWatch&) -> std::string { std::abort(); }, kShort);
    FAIL();
  } catch (const UserCodeError&) {
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("the episode's process crashed (SIGABRT"));
  }
}

// A whole episode of the faulty plugin's components, in a child: the crash and the hang are the
// controller's and the planner's, in their code or in their constructors.
TEST(UserCodeIsolation, EpisodesWithCrashingOrHangingComponentsGiveVerdicts) {
  const auto components =
      loadComponents({testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so"});
  const auto world =
      std::make_shared<const World>(loadWorld(testing::sourceDir() + "/worlds/head_in.yaml"));
  struct Case {
    const char* planner;
    const char* controller;
    const char* reason;
  };
  for (const Case& c :
       {Case{"time-a-star", "segfault-controller",
             "controller segfault-controller crashed (SIGSEGV, Segmentation fault)"},
        Case{"time-a-star", "hanging-controller",
             "controller hanging-controller gave no command within its time limit of 0.3 s"},
        Case{"segfault-planner", "tracking",
             "planner segfault-planner crashed (SIGSEGV, Segmentation fault)"},
        Case{"hanging-planner", "tracking",
             "planner hanging-planner ran past its time limit of 0.3 s"},
        // Constructors too: in a watched process the check makes them there, under the watch.
        Case{"segfault-ctor-planner", "tracking",
             "planner segfault-ctor-planner crashed (SIGSEGV, Segmentation fault)"},
        Case{
            "time-a-star", "hanging-ctor-controller",
            "controller hanging-ctor-controller gave no command within its time limit of 0.3 s"}}) {
    SCOPED_TRACE(std::string(c.planner) + " " + c.controller);
    EpisodeRequest r;
    r.world = world;
    r.components = components;
    r.plan.planner = c.planner;
    r.controller = c.controller;
    const std::string failure = userFailure([&](UserCodeWatch& w) {
      EpisodeRequest watched = r;
      watched.watch = &w;
      return std::string(toString(runEpisodePipeline(watched).verdict.status));
    });
    EXPECT_THAT(failure, HasSubstr(c.reason));
  }
}

}  // namespace user_code_isolation_test
}  // namespace parksim
