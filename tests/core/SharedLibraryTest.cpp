#include "parksim/core/system/SharedLibrary.h"

#include <gtest/gtest.h>

#include <string>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

// libm: the C++ runtime needs it, so it is loaded before any test runs.
constexpr const char* kLoaded = "libm.so.6";
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
  const SharedLibrary libm(kLoaded, "libm", "");
  using Function = double (*)(double);
  const auto square_root = libm.function<Function>("sqrt");
  ASSERT_NE(square_root, nullptr);
  EXPECT_EQ(square_root(6.25), 2.5);
  EXPECT_EQ(libm.find("no_such_function"), nullptr);
  try {
    libm.function<Function>("no_such_function");
    FAIL();
  } catch (const EnvironmentError& e) {
    EXPECT_EQ(std::string(e.what()), "libm: libm.so.6 has no no_such_function");
  }
}

TEST(SharedLibraryTest, IfLoadedLoadsNothing) {
  EXPECT_FALSE(SharedLibrary::ifLoaded(kMissing).has_value());
  const std::optional<SharedLibrary> libm = SharedLibrary::ifLoaded(kLoaded);
  ASSERT_TRUE(libm.has_value());
  EXPECT_NE(libm->find("sqrt"), nullptr);
}

TEST(SharedLibraryTest, MovesItsHandle) {
  SharedLibrary a(kLoaded, "libm", "");
  SharedLibrary b = std::move(a);
  EXPECT_NE(b.find("sqrt"), nullptr);
  a = std::move(b);
  EXPECT_NE(a.find("sqrt"), nullptr);
}

}  // namespace
}  // namespace parksim
