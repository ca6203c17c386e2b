// The third-party headers every parksim library may include, precompiled once per build
// (cmake/TargetDefaults.cmake: the libraries', test programs', command line's and Python
// module's precompiled headers start with these; scripts/fuzz.sh precompiles them for the
// fuzzers). Not included by any source: a source includes what it uses.
//
// The standard headers that parksim's sources include most (counted over parksim/, app/,
// tests/), then Eigen (which comes with parksim_core), nlohmann/json and yaml-cpp. Bullet (5
// files, ~1 s to parse) and OMPL stay out: their include directories belong to a few targets
// only, and Bullet's types must not become visible outside parksim/sim and parksim/collision.
#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
