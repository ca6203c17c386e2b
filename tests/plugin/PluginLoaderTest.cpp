#include "parksim/usercode/PluginLoader.h"

#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/usercode/PluginApi.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;

std::string examplePlugin() {
  return testing::binaryDir() + "/examples/plugins/libparksim_example_plugins.so";
}
std::string testPlugin(const std::string& name) {
  return testing::binaryDir() + "/tests/plugin/lib" + name + ".so";
}

// The message of the Error that loading `path` into `c` throws, "" when it loads.
std::string loadError(Components& c, const std::string& path) {
  try {
    loadPlugin(c, path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PluginLoader, RegistersAPluginsComponentsAndRecordsIt) {
  Components c;
  const std::size_t planners = c.planners.names().size();
  const PluginRecord& r = loadPlugin(c, examplePlugin());
  EXPECT_EQ(r.name, "parksim-examples");
  EXPECT_EQ(r.version, "1.0.0");
  EXPECT_EQ(r.hash, fileHash(examplePlugin()));
  EXPECT_EQ(r.hash.size(), 16u);
  EXPECT_EQ(r.planners, std::vector<std::string>{"example"});
  EXPECT_EQ(r.controllers, std::vector<std::string>{"pure-pursuit"});
  EXPECT_EQ(c.planners.names().size(), planners + 1);
  const PlannerInfo& info = c.planners.find("example").info;
  EXPECT_EQ(info.plugin, "parksim-examples");
  EXPECT_FALSE(info.trusted);
  EXPECT_FALSE(c.controllers.find("pure-pursuit").info.trusted);
  EXPECT_TRUE(c.controllers.find("tracking").info.trusted);
  // Its parameters are declared and checked like a built-in's.
  ASSERT_EQ(info.params.size(), 1u);
  EXPECT_EQ(info.params[0].name, "cell_m");
  EXPECT_THROW((void)c.planners.make("example", {{"cell_m", "-1"}}), Error);
  EXPECT_THROW((void)c.planners.make("example", {{"cells", "1"}}), Error);
  EXPECT_NE(c.planners.make("example", {{"cell_m", "0.05"}}), nullptr);
}

TEST(PluginLoader, RefusesInOneLineWhatItCannotLoad) {
  Components c;
  EXPECT_THAT(loadError(c, "/nonexistent/libx.so"), HasSubstr("no such plugin file"));
  EXPECT_THAT(loadError(c, testPlugin("parksim_broken_plugin_0")),
              HasSubstr("not a parksim plugin (no parksim_plugin entry point"));
  EXPECT_THAT(
      loadError(c, testPlugin("parksim_broken_plugin_1")),
      HasSubstr("built against plugin API " + std::to_string(PARKSIM_PLUGIN_API_VERSION + 1) +
                ", this parksim has " + std::to_string(PARKSIM_PLUGIN_API_VERSION)));
  EXPECT_THAT(loadError(c, testPlugin("parksim_broken_plugin_2")),
              HasSubstr("types differ from this parksim's"));
  EXPECT_THAT(loadError(c, testPlugin("parksim_broken_plugin_3")),
              HasSubstr("registered no planner or controller"));
  EXPECT_THAT(
      loadError(c, testPlugin("parksim_broken_plugin_4")),
      HasSubstr("controller tracking is registered twice (built in, then by plugin taken)"));
  // A text file is not a library.
  EXPECT_THAT(loadError(c, testing::sourceDir() + "/worlds/head_in.yaml"),
              HasSubstr("plugin: cannot load"));
  // Nothing of a refused plugin stays.
  EXPECT_TRUE(c.plugins.empty());
  EXPECT_EQ(c.controllers.names(), Components{}.controllers.names());
  for (const std::string& error : {loadError(c, testPlugin("parksim_broken_plugin_1"))}) {
    EXPECT_EQ(error.find('\n'), std::string::npos);
  }
}

// A plugin whose static initializer dies while it is loaded is refused in one line naming the
// signal; the loading process lives on (it was probed in a child process first).
TEST(PluginLoader, APluginThatCrashesWhileLoadingIsRefusedNotFatal) {
  Components c;
  const std::string segv = loadError(c, testPlugin("parksim_broken_plugin_5"));
  EXPECT_THAT(segv, HasSubstr("libparksim_broken_plugin_5.so: the plugin crashed while it was "
                              "loaded (SIGSEGV"));
  EXPECT_EQ(segv.find('\n'), std::string::npos);
  EXPECT_THAT(loadError(c, testPlugin("parksim_broken_plugin_6")),
              HasSubstr("libparksim_broken_plugin_6.so: the plugin crashed while it was loaded "
                        "(SIGABRT"));
  EXPECT_TRUE(c.plugins.empty());
  // A good plugin still loads after them.
  EXPECT_EQ(loadError(c, examplePlugin()), "");
}

// A plugin whose static initializer never returns is refused once the load time limit has
// passed; its probing process is killed and reaped, so the loading process has no child left.
TEST(PluginLoader, APluginThatHangsWhileLoadingIsRefusedAfterTheLimit) {
  Components c;
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  try {
    loadPlugin(c, testPlugin("parksim_broken_plugin_7"), 1.0);
  } catch (const Error& e) {
    error = e.what();
  }
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_THAT(error, HasSubstr("libparksim_broken_plugin_7.so: the plugin did not finish loading "
                               "within 1 s (its process was killed"));
  EXPECT_THAT(error, HasSubstr("; not loaded"));
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_GE(elapsed_s, 1.0);  // it waited the limit out, no less
  EXPECT_TRUE(c.plugins.empty());
  // No child is left, running or unreaped: this process forks nothing else.
  errno = 0;
  EXPECT_EQ(::waitpid(-1, nullptr, WNOHANG), -1);
  EXPECT_EQ(errno, ECHILD);
  // A good plugin still loads after it.
  EXPECT_EQ(loadError(c, examplePlugin()), "");
}

// The load time limit is checked like the other user-code limits.
TEST(PluginLoader, RefusesALoadTimeLimitOutOfRange) {
  Components c;
  for (const double bad : {0.0, -1.0, 1e9}) {
    try {
      loadPlugin(c, examplePlugin(), bad);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("plugin load time limit: must be in [0.001, 1e+06] s"));
    }
  }
  EXPECT_TRUE(c.plugins.empty());
}

TEST(PluginLoader, AFileOrANameLoadsOnce) {
  Components c;
  loadPlugin(c, examplePlugin());
  EXPECT_THAT(loadError(c, examplePlugin()), HasSubstr("plugin loaded twice"));
  EXPECT_EQ(c.plugins.size(), 1u);
}

TEST(PluginLoader, NoPluginsAreTheBuiltIns) {
  EXPECT_EQ(loadComponents({}), builtInComponents());
  const auto c = loadComponents({examplePlugin(), testPlugin("parksim_faulty_plugin")});
  ASSERT_EQ(c->plugins.size(), 2u);
  EXPECT_EQ(c->plugins[1].name, "parksim-faults");
  EXPECT_NE(c->controllers.tryFind("throwing-controller"), nullptr);
}

}  // namespace
}  // namespace parksim
