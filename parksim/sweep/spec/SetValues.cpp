#include "parksim/sweep/spec/SetValues.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Fnv1a.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014; Vigna's reference constants).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t state) : state_(state) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 bits.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

constexpr double kTwoPi = 6.283185307179586;

// Ten significant digits, read back: what the canonical text then spells exactly.
double rounded(double v) {
  double out = v;
  (void)parseDouble(formatGeneral(v, 10), out);
  return out;
}

}  // namespace

SetAxis::Target SetAxis::target() const {
  if (path.rfind("planner.", 0) == 0) return Target::kPlanner;
  if (path.rfind("controller.", 0) == 0) return Target::kController;
  return Target::kWorld;
}

std::string SetAxis::parameterName() const {
  return target() == Target::kWorld ? std::string() : path.substr(path.find('.') + 1);
}

std::string canonicalNumber(double value) { return formatShortest(value); }

std::string drawSetValue(const SetDistribution& d, const SampleDef& samples, std::uint64_t index,
                         const std::string& path) {
  SplitMix64 rng(fnv1a64("parksim-sample/1;" + std::to_string(samples.seed) + ";" +
                         std::to_string(index) + ";" + path));
  switch (d.kind) {
    case SetDistribution::Kind::kUniform:
      return canonicalNumber(rounded(d.a + (d.b - d.a) * rng.unit()));
    case SetDistribution::Kind::kNormal: {
      const double u1 = rng.unit();
      const double u2 = rng.unit();
      const double z = std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(kTwoPi * u2);
      return canonicalNumber(rounded(d.a + d.b * z));
    }
    case SetDistribution::Kind::kChoice: {
      const auto n = static_cast<double>(d.choices.size());
      const auto k = static_cast<std::size_t>(std::floor(n * rng.unit()));
      return d.choices.at(std::min(k, d.choices.size() - 1));
    }
  }
  return {};
}

nlohmann::ordered_json setValueJson(const std::string& canonical) {
  double number = 0.0;
  if (parseDouble(canonical, number) && std::isfinite(number)) {
    long long whole = 0;
    if (parseInt(canonical, whole)) return whole;
    return number;
  }
  if (canonical == "true") return true;
  if (canonical == "false") return false;
  if (!canonical.empty() && (canonical.front() == '[' || canonical.front() == '{')) {
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(canonical, nullptr, false);
    if (!j.is_discarded()) return j;
  }
  return canonical;
}

std::string setValueYaml(const std::string& canonical) {
  const nlohmann::ordered_json j = setValueJson(canonical);
  return j.is_string() ? j.dump() : canonical;
}

}  // namespace parksim
