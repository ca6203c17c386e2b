#include "parksim/renders/SharedLibrary.h"

#include <gtest/gtest.h>

#include <string>

#include "parksim/core/Error.h"

namespace parksim {
namespace {

// zlib is linked into every render test: loaded before any test runs.
constexpr const char* kLoaded = "libz.so.1";
constexpr const char* kMissing = "libparksim-no-such-library.so.1";

TEST(SharedLibraryTest, MissingLibraryIsAnEnvironmentErrorWithAHint) {
  try {
    SharedLibrary lib(kMissing, "Thing", "install the package thing");
    FAIL() << "loaded " << lib.name();
  } catch (const EnvironmentError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(std::string("Thing: cannot load ") + kMissing + " (", 0), 0u) << what;
    EXPECT_NE(what.find("); install the package thing"), std::string::npos) << what;
  }
}

TEST(SharedLibraryTest, FindsTypedFunctionsAndNamesMissingOnes) {
  const SharedLibrary zlib(kLoaded, "zlib", "");
  using Version = const char* (*)();
  const auto version = zlib.function<Version>("zlibVersion");
  ASSERT_NE(version, nullptr);
  EXPECT_EQ(version()[0], '1');
  EXPECT_EQ(zlib.find("no_such_function"), nullptr);
  try {
    zlib.function<Version>("no_such_function");
    FAIL();
  } catch (const EnvironmentError& e) {
    EXPECT_EQ(std::string(e.what()), "zlib: libz.so.1 has no no_such_function");
  }
}

TEST(SharedLibraryTest, IfLoadedLoadsNothing) {
  EXPECT_FALSE(SharedLibrary::ifLoaded(kMissing).has_value());
  const std::optional<SharedLibrary> zlib = SharedLibrary::ifLoaded(kLoaded);
  ASSERT_TRUE(zlib.has_value());
  EXPECT_NE(zlib->find("zlibVersion"), nullptr);
}

TEST(SharedLibraryTest, MovesItsHandle) {
  SharedLibrary a(kLoaded, "zlib", "");
  SharedLibrary b = std::move(a);
  EXPECT_NE(b.find("zlibVersion"), nullptr);
  a = std::move(b);
  EXPECT_NE(a.find("zlibVersion"), nullptr);
}

}  // namespace
}  // namespace parksim
