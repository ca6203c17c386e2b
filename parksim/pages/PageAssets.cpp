#include "parksim/pages/PageAssets.h"

#include <array>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "parksim/core/io/Error.h"
#include "parksim/pages/ColumnCodec.h"

namespace parksim {

namespace page_assets {
// PageAssetsData.cpp, generated from parksim/pages/CMakeLists.txt's list.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;
}  // namespace page_assets

namespace {

const EmbeddedFile& embeddedFile(std::string_view name) {
  for (std::size_t i = 0; i < page_assets::kEmbeddedFileCount; ++i) {
    const EmbeddedFile& f = page_assets::kEmbeddedFiles[i];
    if (name == f.name) return f;
  }
  throw Error("no page file named " + std::string(name) + " is built in");
}

std::string_view embedded(std::string_view name) {
  const EmbeddedFile& f = embeddedFile(name);
  return {reinterpret_cast<const char*>(f.data), f.size};
}

int hexDigit(char c) { return c <= '9' ? c - '0' : c - 'a' + 10; }

PageFile pageFile(std::string_view name) {
  const EmbeddedFile& f = embeddedFile(name);
  const std::string_view hex = f.sha256;
  std::array<std::uint8_t, 32> digest{};
  if (hex.size() != 2 * digest.size()) throw Error(std::string(name) + ": no SHA-256 built in");
  for (std::size_t i = 0; i < digest.size(); ++i) {
    digest[i] = static_cast<std::uint8_t>(16 * hexDigit(hex[2 * i]) + hexDigit(hex[2 * i + 1]));
  }
  return {{reinterpret_cast<const char*>(f.data), f.size}, base64(digest)};
}

struct LibraryFiles {
  const char* package;
  const char* title;
  const char* script;
  const char* style;
};

constexpr LibraryFiles kLibraries[] = {
    {"uplot", "uPlot", "uplot/dist/uPlot.iife.min.js", "uplot/dist/uPlot.min.css"},
    {"tabulator-tables", "Tabulator", "tabulator-tables/dist/js/tabulator.min.js",
     "tabulator-tables/dist/css/tabulator_simple.min.css"},
};

PageLibrary load(const LibraryFiles& files) {
  const std::string dir = files.package;
  const nlohmann::json package = nlohmann::json::parse(embedded(dir + "/package.json"));
  PageLibrary lib;
  lib.package = files.package;
  lib.title = files.title;
  lib.version = package.value("version", "");
  lib.license = package.value("license", "");
  lib.homepage = package.value("homepage", "");
  lib.script = pageFile(files.script);
  lib.style = pageFile(files.style);
  lib.license_text = embedded(dir + "/LICENSE");
  return lib;
}

}  // namespace

const PageLibrary& pageLibrary(PageLibraryId id) {
  // Read once: the package.json files are parsed on first use.
  static const std::array<PageLibrary, 2> libraries = {load(kLibraries[0]), load(kLibraries[1])};
  return libraries.at(static_cast<std::size_t>(id));
}

PageFile pageSource(std::string_view name) { return pageFile("web/" + std::string(name)); }

std::vector<std::string> embeddedFileNames() {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < page_assets::kEmbeddedFileCount; ++i) {
    names.emplace_back(page_assets::kEmbeddedFiles[i].name);
  }
  return names;
}

}  // namespace parksim
