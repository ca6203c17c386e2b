// Making a component to check its parameters (ComponentCheck.h): a plugin's constructor that
// crashes or hangs is a one-line refusal naming it, in this process's stead; parksim's own and
// the plugin's sound components are made as before.

#include "parksim/usercode/ComponentCheck.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/usercode/PluginLoader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using Kind = ComponentParams::Kind;

// Short limits: a hanging constructor never ends, so only the limit ends it.
constexpr UserCodeLimits kShort{0.3, 0.3};
const ComponentCheckDef kCheck{.limits = kShort, .isolate = true};

std::shared_ptr<const Components> faulty() {
  return loadComponents({testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so"});
}

TEST(ComponentCheck, SoundComponentsAreMadeAndBadParametersRefusedAsTheRegistryRefusesThem) {
  const auto components = faulty();
  const std::vector<ComponentParams> sound = {
      {Kind::kPlanner, "time-a-star", {}},
      {Kind::kController, "tracking-copy", {}},
      {Kind::kPlanner, "segfault-ctor-planner", {{"fault_above", "1"}}},
      {Kind::kController, "hanging-ctor-controller", {{"fault_above", "1"}}}};
  EXPECT_FALSE(firstRefusedComponent(*components, sound, kCheck));
  // A plugin's unknown parameter: the registry's message, from the watched process.
  std::string expected;
  try {
    (void)components->planners.make("segfault-ctor-planner", {{"faults", "1"}});
  } catch (const Error& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  std::vector<ComponentParams> list = sound;
  list.push_back({Kind::kPlanner, "segfault-ctor-planner", {{"faults", "1"}}});
  std::optional<ComponentRefusal> refused = firstRefusedComponent(*components, list, kCheck);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->index, 4u);
  EXPECT_EQ(refused->message, expected);
  // An unknown name, before anything is made.
  refused = firstRefusedComponent(*components, {{Kind::kController, "trackin", {}}}, kCheck);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->index, 0u);
  EXPECT_EQ(refused->message.rfind("unknown controller 'trackin' (expected one of ", 0), 0u)
      << refused->message;
}

TEST(ComponentCheck, AConstructorThatCrashesOrHangsIsNamedNotFatal) {
  const auto components = faulty();
  struct Case {
    ComponentParams component;
    const char* message;
  };
  for (const Case& c :
       {Case{{Kind::kPlanner, "segfault-ctor-planner", {}},
             "planner segfault-ctor-planner crashed (SIGSEGV, Segmentation fault) while being "
             "made to check its parameters"},
        Case{
            {Kind::kController, "segfault-ctor-controller", {{"value", "2"}, {"fault_above", "1"}}},
            "controller segfault-ctor-controller crashed (SIGSEGV, Segmentation fault) while "
            "being made to check its parameters"},
        Case{{Kind::kPlanner, "hanging-ctor-planner", {}},
             "planner hanging-ctor-planner ran past its time limit of 0.3 s (its process was "
             "killed) while being made to check its parameters"},
        Case{{Kind::kController, "hanging-ctor-controller", {}},
             "controller hanging-ctor-controller gave no command within its time limit of 0.3 s "
             "(its process was killed) while being made to check its parameters"}}) {
    SCOPED_TRACE(c.component.name);
    // Sound ones before it, made in the same process as it; the one after it is never made.
    const std::vector<ComponentParams> list = {
        {Kind::kPlanner, "through-walls", {}},
        {c.component.kind, c.component.name, {{"fault_above", "1"}}},
        c.component,
        {Kind::kPlanner, "segfault-ctor-planner", {}}};
    const std::optional<ComponentRefusal> refused =
        firstRefusedComponent(*components, list, kCheck);
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->index, 2u);
    EXPECT_EQ(refused->message, c.message);
    try {
      checkComponents(*components, list, kCheck);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_STREQ(e.what(), c.message);
    }
  }
}

TEST(ComponentCheck, UnderAWatchEveryComponentIsMadeHereAndAUsersConstructorIsWatched) {
  const auto components = faulty();
  UserCodeWatch watch;
  const std::uint64_t before = watch.beats();
  // parksim's own: not watched.
  checkComponents(*components, {{Kind::kController, "tracking", {}}}, {kShort, {}, &watch});
  EXPECT_EQ(watch.beats(), before);
  // The plugin's: entered and left, here (a crash would end this process, as the watching
  // process expects of its worker).
  checkComponents(*components, {{Kind::kController, "tracking-copy", {}}}, {kShort, {}, &watch});
  EXPECT_EQ(watch.beats(), before + 2);
  EXPECT_EQ(watch.phase(), UserCodeWatch::Phase::kParksim);
}

// Without isolate (the library's runEpisodePipeline, Python's run(): they make and run the
// plugin in their own process right after), a plugin's constructor is made in the calling
// process, with no fork: its crash is this process's.
TEST(ComponentCheckDeathTest, WithoutIsolationAPluginIsMadeInTheCallingProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto components = faulty();
  const std::vector<ComponentParams> crashing = {{Kind::kPlanner, "segfault-ctor-planner", {}}};
  EXPECT_DEATH((void)firstRefusedComponent(*components, crashing, {.limits = kShort}), "");
  // Isolated, the same list is a refusal.
  EXPECT_TRUE(firstRefusedComponent(*components, crashing, kCheck));
}

}  // namespace
}  // namespace parksim
