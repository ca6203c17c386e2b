#pragma once
// What the page tests share: a page's embedded data read back from its HTML, and its packed
// columns unpacked as web/common.js unpacks them.

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim::testing {

/// RFC 4648 base64 decoded (the page's atob).
inline std::vector<std::uint8_t> fromBase64(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    int v = -1;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    if (c >= '0' && c <= '9') v = c - '0' + 52;
    if (c == '+') v = 62;
    if (c == '/') v = 63;
    if (v < 0) continue;  // '=' padding
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<std::uint8_t>((bits >> count) & 0xFF));
    }
  }
  return out;
}

/// A packed column's values as doubles (an integer column's offset added, its missing marker
/// as NaN), as parksim.column() makes them.
inline std::vector<double> unpack(const nlohmann::json& column) {
  const std::vector<std::uint8_t> bytes = fromBase64(column.at("data").get<std::string>());
  const std::string type = column.at("type");
  std::vector<double> values;
  const auto read = [&](auto sample) {
    using T = decltype(sample);
    for (std::size_t i = 0; i + sizeof(T) <= bytes.size(); i += sizeof(T)) {
      T v;
      std::memcpy(&v, bytes.data() + i, sizeof(T));
      double x = static_cast<double>(v);
      if (column.contains("missing") && x == column.at("missing").get<double>()) {
        x = std::nan("");
      } else if (column.contains("offset")) {
        x += column.at("offset").get<double>();
      }
      values.push_back(x);
    }
  };
  if (type == "f64") read(double{});
  if (type == "f32") read(float{});
  if (type == "u8") read(std::uint8_t{});
  if (type == "u16") read(std::uint16_t{});
  if (type == "u32") read(std::uint32_t{});
  return values;
}

/// The text of the element whose opening tag is `open`.
inline std::string elementText(const std::string& html, const std::string& open) {
  const std::size_t begin = html.find(open);
  if (begin == std::string::npos) throw std::runtime_error("no " + open + " in the page");
  const std::size_t end = html.find("</script>", begin);
  return html.substr(begin + open.size(), end - begin - open.size());
}

/// Puts each packed column's base64 text back as its "data", from its blob element.
inline void resolveBlobs(nlohmann::json& data, const std::string& html) {
  if (data.is_object() && data.contains("blob") && data.contains("type")) {
    const std::string id = std::to_string(data["blob"].get<int>());
    data["data"] = elementText(html, "<script type=\"text/plain\" id=\"parksim-blob-" + id + "\">");
    data.erase("blob");
    return;
  }
  if (data.is_structured()) {
    for (auto& item : data) resolveBlobs(item, html);
  }
}

/// The JSON a page's <script id="parksim-data"> holds, its columns' blobs put back.
inline nlohmann::json pageData(const std::string& html) {
  nlohmann::json data = nlohmann::json::parse(
      elementText(html, "<script type=\"application/json\" id=\"parksim-data\">"));
  resolveBlobs(data, html);
  return data;
}

}  // namespace parksim::testing
