#include "parksim/usercode/CommandLine.h"

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/system/ChildProcess.h"

namespace parksim {

std::vector<std::string> splitCommandLine(const std::string& text, const std::string& what) {
  if (text.size() > kMaxCommandBytes) {
    throw Error(what + ": the command is " + std::to_string(text.size()) +
                " bytes, more than the limit of " + std::to_string(kMaxCommandBytes) +
                " (docs/limits.md)");
  }
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;  // a word has started (it may be empty: '')
  auto end_word = [&] {
    if (!in_word) return;
    words.push_back(std::move(word));
    word.clear();
    in_word = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == '\n') {
      end_word();
    } else if (c == '\'') {
      const std::size_t close = text.find('\'', i + 1);
      if (close == std::string::npos) throw Error(what + ": unterminated ' quote");
      word.append(text, i + 1, close - i - 1);
      in_word = true;
      i = close;
    } else if (c == '"') {
      in_word = true;
      ++i;
      while (i < text.size() && text[i] != '"') {
        // Inside double quotes a backslash escapes only these, as in a shell.
        if (text[i] == '\\' && i + 1 < text.size() &&
            std::string_view("\"\\$`").find(text[i + 1]) != std::string_view::npos) {
          ++i;
        }
        word += text[i++];
      }
      if (i >= text.size()) throw Error(what + ": unterminated \" quote");
    } else if (c == '\\') {
      if (i + 1 >= text.size()) throw Error(what + ": a backslash ends the command");
      word += text[++i];
      in_word = true;
    } else {
      word += c;
      in_word = true;
    }
  }
  end_word();
  if (words.empty()) throw Error(what + ": no command given");
  if (words.size() > kMaxCommandWords) {
    throw Error(what + ": the command has " + std::to_string(words.size()) +
                " words, more than the limit of " + std::to_string(kMaxCommandWords) +
                " (docs/limits.md)");
  }
  return words;
}

std::string quoteCommandLine(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) {
    if (!out.empty()) out += ' ';
    if (!w.empty() && w.find_first_of(" \t\n'\"\\") == std::string::npos) {
      out += w;
      continue;
    }
    out += shellQuoted(w);
  }
  return out;
}

std::vector<std::string> substitutePlaceholders(std::vector<std::string> words,
                                                const std::map<std::string, std::string>& values) {
  for (std::string& w : words) {
    std::string out;
    std::size_t i = 0;
    while (i < w.size()) {
      bool replaced = false;
      if (w[i] == '{') {
        for (const auto& [name, value] : values) {
          if (w.compare(i + 1, name.size(), name) == 0 && i + 1 + name.size() < w.size() &&
              w[i + 1 + name.size()] == '}') {
            out += value;
            i += name.size() + 2;
            replaced = true;
            break;
          }
        }
      }
      if (!replaced) out += w[i++];
    }
    w = std::move(out);
  }
  return words;
}

std::vector<std::string> commandParam(const ParamMap& params, const std::string& owner,
                                      const std::string& required) {
  const auto it = params.find(kCommandParam);
  if (it == params.end()) {
    throw Error(owner + ": parameter " + kCommandParam + " is required: the command line to run" +
                (required.empty() ? std::string() : ", with " + required));
  }
  const std::string what = owner + ": parameter " + kCommandParam;
  std::vector<std::string> words = splitCommandLine(it->second, what);
  if (findExecutable(words[0]).empty()) {
    throw Error(what + ": " + escapeText(words[0]) +
                (words[0].find('/') != std::string::npos ? " is not an executable file"
                                                         : " is no program in PATH"));
  }
  if (!required.empty()) {
    bool found = false;
    for (const std::string& w : words) found = found || w.find(required) != std::string::npos;
    if (!found) throw Error(what + ": the command has no " + required);
  }
  return words;
}

std::vector<ParamInfo> commandParamInfos(const std::string& description, const ParamSet& known) {
  std::vector<ParamInfo> infos = {
      {kCommandParam, "", description, "a command line (docs/your-code.md)"}};
  infos.insert(infos.end(), known.infos().begin(), known.infos().end());
  return infos;
}

std::string shownCommand(const std::vector<std::string>& words) {
  return escapeTextShortened(quoteCommandLine(words), 160);
}

ParamMap applyKnownParams(const ParamMap& params, const ParamSet& known) {
  ParamMap mine;
  ParamMap passed;
  for (const auto& [name, value] : params) {
    if (name == kCommandParam) continue;
    bool declared = false;
    for (const ParamInfo& info : known.infos()) declared = declared || info.name == name;
    (declared ? mine : passed)[name] = value;
  }
  known.apply(mine);
  return passed;
}

}  // namespace parksim
