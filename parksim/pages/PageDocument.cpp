#include "parksim/pages/PageDocument.h"

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/results/reports/XmlText.h"

namespace parksim {
namespace {

std::string text(std::string_view s) { return xmlEscaped(s, XmlContext::kContent); }

// JSON inside a <script> element: '<' only occurs inside strings, where \u003c means the same
// and cannot close the element or open a comment.
std::string scriptJson(const nlohmann::json& data) {
  std::string json = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  for (std::size_t at = json.find('<'); at != std::string::npos; at = json.find('<', at)) {
    json.replace(at, 1, "\\u003c");
  }
  return json;
}

// Moves the base64 text of every packed column (ColumnCodec.h: an object with a string "type"
// and a string "data") out of `data` into `blobs`, leaving "blob": its index. The page reads
// them from their own elements (web/common.js): nothing to parse, nothing to escape, and the
// JSON stays small.
void extractBlobs(nlohmann::json& data, std::vector<std::string>& blobs) {
  if (data.is_array()) {
    for (nlohmann::json& item : data) extractBlobs(item, blobs);
    return;
  }
  if (!data.is_object()) return;
  const auto type = data.find("type");
  const auto bytes = data.find("data");
  if (type != data.end() && type->is_string() && bytes != data.end() && bytes->is_string()) {
    blobs.push_back(std::move(bytes->get_ref<std::string&>()));
    data.erase(bytes);
    data["blob"] = blobs.size() - 1;
    return;
  }
  for (auto& [key, value] : data.items()) extractBlobs(value, blobs);
}

// The inline scripts and style sheets, each one element holding one file whole.
struct PageParts {
  std::vector<PageFile> styles;
  std::vector<std::string> script_notes;  ///< what each script is, said before its element
  std::vector<PageFile> scripts;
};

PageParts partsOf(const PageDocument& page) {
  PageParts parts;
  for (const PageLibraryId id : page.libraries) {
    const PageLibrary& lib = pageLibrary(id);
    parts.styles.push_back(lib.style);
    parts.scripts.push_back(lib.script);
    parts.script_notes.push_back(lib.title + " " + lib.version + " (" + lib.license +
                                 "; licence text in this page's footer)");
  }
  parts.styles.push_back(pageSource("page.css"));
  parts.scripts.push_back(pageSource("common.js"));
  parts.script_notes.emplace_back("parksim");
  for (const std::string& script : page.scripts) {
    parts.scripts.push_back(pageSource(script));
    parts.script_notes.emplace_back();
  }
  return parts;
}

// Nothing may be fetched (scripts and styles are inline, images are drawn into canvases), and
// nothing runs or styles the page but the files it was made with, each allowed by its hash:
// no inline script or style a name might smuggle in, no event handler attribute, no
// javascript: link. (The data's <script type="application/json"> and blobs are not run.)
std::string contentSecurityPolicy(const PageParts& parts) {
  std::string csp = "default-src 'none'; script-src";
  for (const PageFile& f : parts.scripts) csp += " 'sha256-" + f.sha256_base64 + "'";
  csp += "; style-src";
  for (const PageFile& f : parts.styles) csp += " 'sha256-" + f.sha256_base64 + "'";
  csp += "; img-src data:; form-action 'none'; base-uri 'none'";
  return csp;
}

void appendLicences(std::string& html, const PageDocument& page) {
  html += "<footer><details><summary>Made by " + text(versionLine(buildProvenance())) + " with ";
  for (std::size_t i = 0; i < page.libraries.size(); ++i) {
    const PageLibrary& lib = pageLibrary(page.libraries[i]);
    if (i > 0) html += i + 1 == page.libraries.size() ? " and " : ", ";
    html += text(lib.title + " " + lib.version + " (" + lib.license + ")");
  }
  html += "; their licences, which this file carries with their code:</summary>\n";
  for (const PageLibraryId id : page.libraries) {
    const PageLibrary& lib = pageLibrary(id);
    html += "<h3>" + text(lib.title + " " + lib.version) + " — " + text(lib.homepage) +
            "</h3>\n<pre>" + text(lib.license_text) + "</pre>\n";
  }
  html += "</details></footer>\n";
}

}  // namespace

std::string pageHtml(PageDocument page) {
  const PageParts parts = partsOf(page);
  std::string html;
  html.reserve(1u << 20);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta http-equiv=\"Content-Security-Policy\" content=\"";
  html += contentSecurityPolicy(parts);
  html += "\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += "<meta name=\"generator\" content=\"" +
          xmlEscaped(versionLine(buildProvenance()), XmlContext::kAttribute) + "\">\n";
  html += "<title>" + text(page.title) + "</title>\n";
  // Each element's text is the file's bytes exactly, so that it has the hash the policy names.
  for (const PageFile& style : parts.styles) {
    html += "<style>";
    html += style.text;
    html += "</style>\n";
  }
  html +=
      "</head>\n<body>\n<noscript>This report draws itself with JavaScript; "
      "allow it for this file.</noscript>\n<main id=\"page\"></main>\n";
  appendLicences(html, page);
  std::vector<std::string> blobs;
  extractBlobs(page.data, blobs);
  html += "<script type=\"application/json\" id=\"parksim-data\">";
  html += scriptJson(page.data);
  html += "</script>\n";
  // Base64 holds no '<': each blob is the text of its element as it is.
  for (std::size_t i = 0; i < blobs.size(); ++i) {
    html += "<script type=\"text/plain\" id=\"parksim-blob-" + std::to_string(i) + "\">";
    html += blobs[i];
    html += "</script>\n";
  }
  for (std::size_t i = 0; i < parts.scripts.size(); ++i) {
    if (!parts.script_notes[i].empty()) html += "<!-- " + text(parts.script_notes[i]) + " -->\n";
    html += "<script>";
    html += parts.scripts[i].text;
    html += "</script>\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

void writePage(const std::string& path, PageDocument page) {
  writeFileAtomically(path, pageHtml(std::move(page)));
}

}  // namespace parksim
