#include "parksim/results/tables/RowSeal.h"

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Fnv1a.h"

namespace parksim {
namespace {

// `,"row_checksum":"` + 16 hex digits + `"}`.
constexpr std::string_view kSealHead = ",\"row_checksum\":\"";
static_assert(kSealHead.substr(2, kRowChecksumKey.size()) == kRowChecksumKey);
constexpr std::size_t kHexDigits = 16;
constexpr std::size_t kSealLength = kSealHead.size() + kHexDigits + 2;

// The checksum of `body` (a line without its seal, i.e. without the closing '}') as if it were
// closed: the hash of body + "}", without building that string.
std::string checksumOfOpenObject(std::string_view body) {
  return hex16(fnv1a64("}", fnv1a64(body)));
}

bool isHex(std::string_view s) {
  for (const char c : s) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

}  // namespace

SealedRow sealRow(const nlohmann::ordered_json& row) {
  if (!row.is_object() || row.empty()) throw Error("sealRow: a row is a JSON object with keys");
  if (row.contains(kRowChecksumKey)) throw Error("sealRow: the row is sealed already");
  std::string text = row.dump();
  text.pop_back();  // the closing '}'
  SealedRow sealed;
  sealed.checksum = checksumOfOpenObject(text);
  sealed.line = std::move(text);
  sealed.line += kSealHead;
  sealed.line += sealed.checksum;
  sealed.line += "\"}";
  return sealed;
}

std::optional<std::string> sealProblem(std::string_view line) {
  const bool has_seal = line.size() > kSealLength + 1 &&
                        line.substr(line.size() - kSealLength, kSealHead.size()) == kSealHead &&
                        line.substr(line.size() - 2) == "\"}" &&
                        isHex(line.substr(line.size() - kHexDigits - 2, kHexDigits));
  if (!has_seal) {
    return "no row_checksum as its last key: not a row this parksim wrote (a hand-written row, "
           "a damaged end of line, or a table of parksim 0.3.0 or earlier)";
  }
  const std::string_view body = line.substr(0, line.size() - kSealLength);
  const std::string_view stated = line.substr(line.size() - kHexDigits - 2, kHexDigits);
  if (checksumOfOpenObject(body) != stated) {
    return "row_checksum " + std::string(stated) +
           " does not match the row's content: the row changed after parksim wrote it";
  }
  return std::nullopt;
}

std::string rowWriter(const nlohmann::ordered_json& row) {
  const auto text = [&row](const char* key) {
    const auto it = row.find(key);
    if (it == row.end()) return std::string("?");
    return it->is_string() ? it->get<std::string>() : it->dump();
  };
  std::string commit = text("git_commit").substr(0, 12);
  const auto dirty = row.find("git_dirty");
  if (dirty != row.end() && dirty->is_boolean() && dirty->get<bool>()) commit += "-dirty";
  // The plugins are part of the code that wrote the row: another build of a user's plugin is
  // another writer.
  const auto plugins = row.find("plugins");
  const std::string with =
      plugins != row.end() && plugins->is_string() && !plugins->get<std::string>().empty()
          ? "; plugins " + plugins->get<std::string>()
          : std::string();
  return "parksim " + text("parksim_version") + " (commit " + commit + ", " + text("build_type") +
         ", " + text("compiler") + ", Bullet " + text("bullet_precision") + with + ")";
}

}  // namespace parksim
