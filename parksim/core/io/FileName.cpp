#include "parksim/core/io/FileName.h"

#include "parksim/core/io/Fnv1a.h"

namespace parksim {

namespace {

bool plain(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

}  // namespace

std::string fileStemOf(std::string_view name) {
  bool as_is = !name.empty() && name.size() <= kMaxFileStem && name.front() != '.';
  for (const char c : name) as_is = as_is && plain(c);
  if (as_is) return std::string(name);
  // The hash keeps apart what the replacement and the cut would join ("a/b" and "a_b").
  const std::string suffix = "-" + hex16(fnv1a64(name));
  std::string stem;
  for (const char c : name.substr(0, kMaxFileStem - suffix.size())) stem += plain(c) ? c : '_';
  if (!stem.empty() && stem.front() == '.') stem.front() = '_';
  return stem + suffix;
}

}  // namespace parksim
