#include "parksim/scenario/maps/MovingAiMap.h"

#include <charconv>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/Text.h"
#include "parksim/scenario/maps/MapLimits.h"

namespace parksim {

namespace {

class MovingAiLines {
 public:
  MovingAiLines(const std::string& path, std::string_view text) : path_(path), text_(text) {}

  // The next line without its end (\n or \r\n); false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = text_.find('\n', pos_);
    line = text_.substr(pos_, end == std::string_view::npos ? std::string_view::npos : end - pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_;
    return true;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(escapeText(path_ + ":" + std::to_string(line_) + ": " + what));
  }

  // "key value" on the next line, the value a whole number.
  std::int64_t header(std::string_view key) {
    std::string_view line;
    if (!next(line)) fail("the file ends before its '" + std::string(key) + "' line");
    if (line.substr(0, key.size() + 1) != std::string(key) + " ") {
      fail("expected '" + std::string(key) + " <number>', got '" + std::string(line) + "'");
    }
    const std::string_view digits = line.substr(key.size() + 1);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size()) {
      fail(std::string(key) + ": expected a whole number, got '" + std::string(digits) + "'");
    }
    return v;
  }

  int line() const { return line_; }

 private:
  const std::string& path_;
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

struct MovingAiHeader {
  std::int64_t height = 0;
  std::int64_t width = 0;
};

// The header's lines up to `map`, checked against the limits.
MovingAiHeader readHeader(MovingAiLines& lines) {
  std::string_view line;
  if (!lines.next(line) || line != "type octile") {
    lines.fail("expected 'type octile' (a Moving AI .map file), got '" + std::string(line) + "'");
  }
  MovingAiHeader h;
  h.height = lines.header("height");
  h.width = lines.header("width");
  if (h.width < 1 || h.height < 1 || h.width > kMaxMapSideCells || h.height > kMaxMapSideCells ||
      h.width * h.height > kMaxMapCells) {
    lines.fail("the map is " + std::to_string(h.width) + " x " + std::to_string(h.height) +
               " cells; a map has at least one and at most " + std::to_string(kMaxMapSideCells) +
               " a side and " + std::to_string(kMaxMapCells) + " in all (docs/limits.md)");
  }
  if (!lines.next(line) || line != "map")
    lines.fail("expected 'map', got '" + std::string(line) + "'");
  return h;
}

// Bytes enough for any header a reader accepts: its four lines are short.
constexpr std::size_t kHeaderBytes = 4096;

}  // namespace

std::shared_ptr<const OccupancyGrid> readMovingAiMap(const std::string& path, double cell_m,
                                                     const Pose2& origin,
                                                     std::vector<std::string>* warnings) {
  {
    // The header alone decides the limits: checked before the grid's bytes are read.
    const std::string head = readInputFileHead(path, kHeaderBytes, "Moving AI map");
    MovingAiLines head_lines(path, head);
    (void)readHeader(head_lines);
  }
  const std::string text = readInputFile(path, kMaxMapFileBytes, "Moving AI map");
  MovingAiLines lines(path, text);
  const auto [height, width] = readHeader(lines);
  std::string_view line;
  auto grid = std::make_shared<OccupancyGrid>();
  grid->width = static_cast<int>(width);
  grid->height = static_cast<int>(height);
  grid->resolution_m = cell_m;
  grid->origin = origin;
  grid->cells.resize(static_cast<std::size_t>(width * height));
  for (std::int64_t r = 0; r < height; ++r) {
    if (!lines.next(line)) {
      lines.fail("size mismatch: the header says " + std::to_string(height) +
                 " rows, the file ends after " + std::to_string(r));
    }
    if (static_cast<std::int64_t>(line.size()) != width) {
      lines.fail("size mismatch: the row has " + std::to_string(line.size()) +
                 " cells, the header says width " + std::to_string(width));
    }
    const std::size_t j = static_cast<std::size_t>(height - 1 - r);  // first row on top
    for (std::size_t i = 0; i < line.size(); ++i) {
      MapCell cell = MapCell::kFree;
      switch (line[i]) {
        case '.':
        case 'G':
        case 'S': cell = MapCell::kFree; break;
        case '@':
        case 'O':
        case 'T':
        case 'W': cell = MapCell::kOccupied; break;
        default:
          lines.fail("column " + std::to_string(i + 1) + ": '" + std::string(1, line[i]) +
                     "' is no Moving AI terrain (. G S passable, @ O T W blocked)");
      }
      grid->cells[j * static_cast<std::size_t>(width) + i] = static_cast<std::uint8_t>(cell);
    }
  }
  // Moving AI's own readers read the header's rows and stop: text after them is ignored, and
  // said so, since it may be rows the header does not count.
  while (lines.next(line)) {
    if (line.empty()) continue;
    if (warnings) {
      warnings->push_back(escapeText(
          path + ":" + std::to_string(lines.line()) + ": trailing text after the header's " +
          std::to_string(height) + " rows; ignored, as Moving AI's readers ignore it"));
    }
    break;
  }
  return grid;
}

}  // namespace parksim
