#include "parksim/core/params/ParamSet.h"

#include <cmath>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"

namespace parksim {

namespace {

std::string rangeText(double min, double max) {
  return "[" + formatShortest(min) + ", " + formatShortest(max) + "]";
}

double parseReal(const std::string& text, double min, double max) {
  double v = 0.0;
  if (!parseDouble(text, v) || !(v >= min && v <= max)) {
    throw Error("expected a number in " + rangeText(min, max) + ", got '" + text + "'");
  }
  return v;
}

std::string trimmed(const std::string& text) {
  const std::size_t b = text.find_first_not_of(' ');
  if (b == std::string::npos) return {};
  return text.substr(b, text.find_last_not_of(' ') - b + 1);
}

std::string listText(const std::vector<double>& values) {
  std::string out;
  for (double v : values) {
    if (!out.empty()) out += ',';
    out += formatShortest(v);
  }
  return out;
}

}  // namespace

ParamSet::ParamSet(std::string owner) : owner_(std::move(owner)) {}

void ParamSet::declare(ParamInfo info, std::function<void(const std::string&)> set) {
  for (const ParamInfo& known : infos_) {
    if (known.name == info.name) throw Error(owner_ + ": parameter " + info.name + " twice");
  }
  infos_.push_back(std::move(info));
  bindings_.push_back({std::move(set)});
}

void ParamSet::add(const std::string& name, double* field, const std::string& description,
                   double min, double max) {
  declare({name, formatShortest(*field), description, rangeText(min, max)},
          [field, min, max](const std::string& text) { *field = parseReal(text, min, max); });
}

void ParamSet::add(const std::string& name, int* field, const std::string& description, int min,
                   int max) {
  declare({name, std::to_string(*field), description,
           "[" + std::to_string(min) + ", " + std::to_string(max) + "]"},
          [field, min, max](const std::string& text) {
            long long v = 0;
            if (!parseInt(text, v) || v < min || v > max) {
              throw Error("expected an integer in [" + std::to_string(min) + ", " +
                          std::to_string(max) + "], got '" + text + "'");
            }
            *field = static_cast<int>(v);
          });
}

void ParamSet::add(const std::string& name, bool* field, const std::string& description) {
  declare({name, *field ? "true" : "false", description, "true|false"},
          [field](const std::string& text) {
            if (text != "true" && text != "false") {
              throw Error("expected true or false, got '" + text + "'");
            }
            *field = text == "true";
          });
}

void ParamSet::add(const std::string& name, std::string* field, const std::string& description,
                   const std::vector<std::string>& choices) {
  std::string range;
  for (const std::string& c : choices) range += (range.empty() ? "" : "|") + c;
  declare({name, *field, description, range}, [field, choices](const std::string& text) {
    for (const std::string& c : choices) {
      if (text == c) {
        *field = text;
        return;
      }
    }
    throw Error("expected one of " + joinNames(choices) + ", got '" + text + "'");
  });
}

void ParamSet::add(const std::string& name, std::vector<double>* field,
                   const std::string& description, double min, double max, int max_count) {
  declare(
      {name, listText(*field), description,
       "1 to " + std::to_string(max_count) + " comma-separated numbers in " + rangeText(min, max)},
      [field, min, max, max_count](const std::string& text) {
        std::vector<double> values;
        std::size_t begin = 0;
        while (begin <= text.size()) {
          const std::size_t comma = std::min(text.find(',', begin), text.size());
          const std::string item = trimmed(text.substr(begin, comma - begin));
          values.push_back(parseReal(item, min, max));
          if (static_cast<int>(values.size()) > max_count) {
            throw Error("expected at most " + std::to_string(max_count) + " numbers");
          }
          begin = comma + 1;
        }
        *field = std::move(values);
      });
}

void ParamSet::apply(const ParamMap& params) const {
  for (const auto& [name, value] : params) {
    std::size_t i = 0;
    while (i < infos_.size() && infos_[i].name != name) ++i;
    if (i == infos_.size()) {
      std::vector<std::string> known;
      for (const ParamInfo& info : infos_) known.push_back(info.name);
      throw Error(owner_ + ": unknown parameter '" + name + "' (" +
                  (known.empty() ? std::string("it takes none") : "known: " + joinNames(known)) +
                  ")");
    }
    try {
      bindings_[i].set(value);
    } catch (const Error& e) {
      throw Error(owner_ + ": parameter " + name + ": " + e.what());
    }
  }
}

std::string canonicalParamText(const std::string& text) {
  double v = 0.0;
  if (parseDouble(text, v) && std::isfinite(v)) return formatShortest(v);
  return text;
}

std::pair<std::string, std::string> splitParamAssignment(const std::string& text,
                                                         const std::string& what) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw Error(what + ": expected NAME=VALUE, got '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace parksim
