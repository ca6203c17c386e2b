#pragma once
// A command as one line of text: how `--planner-command`, `--controller-command` and the
// `command` parameter of the command planner and controller (a ParamMap value, ParamMap.h) hold
// a program and its arguments. No shell runs it: the text is only split into words, with a
// shell's quoting rules and none of its expansions (no variables, globs, pipes or
// redirections), and the words are passed to the program as they are.

#include <map>
#include <string>
#include <vector>

#include "parksim/core/params/ParamMap.h"
#include "parksim/core/params/ParamSet.h"

namespace parksim {

/// The parameter of the command planner and the command controller that holds the command.
inline constexpr const char* kCommandParam = "command";

/// Splits `text` into words as a POSIX shell does, expanding nothing: words are separated by
/// blanks (space, tab, newline); '...' quotes everything up to the next '; "..." quotes with
/// \" \\ \$ \` as escapes; a backslash outside quotes takes the next character literally.
/// Throws Error naming `what` on an unterminated quote, a trailing backslash, no words, more
/// than kMaxCommandWords words or more than kMaxCommandBytes bytes.
std::vector<std::string> splitCommandLine(const std::string& text, const std::string& what);

/// The canonical text of `words`: each word as it is when it holds none of blank, ', ", \ and
/// is not empty, otherwise in single quotes (a ' inside written as '\''). splitCommandLine
/// gives `words` back. Two spellings of one command (`a  'b'` and `a b`) have one canonical
/// text, so they name the same episode (episode ids hash parameter text).
std::string quoteCommandLine(const std::vector<std::string>& words);

/// `words` with every occurrence of "{NAME}" for each NAME in `values` replaced by its value
/// ("--out={out}" works too); other braces are left as they are.
std::vector<std::string> substitutePlaceholders(std::vector<std::string> words,
                                                const std::map<std::string, std::string>& values);

/// The command parameter (kCommandParam) of `params` split into words, its program found (a
/// path, or a name in $PATH). Throws Error prefixed by `owner` ("planner command") when it is
/// missing, cannot be split, or names no program, or when no word contains `required` (a
/// placeholder, e.g. "{out}"; none when empty).
std::vector<std::string> commandParam(const ParamMap& params, const std::string& owner,
                                      const std::string& required);

/// A command planner's or controller's parameters as listed (`parksim list`, help texts): the
/// command parameter, described by `description`, then those `known` declares.
std::vector<ParamInfo> commandParamInfos(const std::string& description, const ParamSet& known);

/// `words` for messages: their canonical text, control bytes escaped, at most 160 bytes.
std::string shownCommand(const std::vector<std::string>& words);

/// `params` split into those `known` declares (applied to it: it throws Error on a bad value)
/// and the rest, returned: what a command planner or controller hands on to its program.
/// kCommandParam is in neither.
ParamMap applyKnownParams(const ParamMap& params, const ParamSet& known);

/// Limits of a command line (docs/limits.md).
inline constexpr std::size_t kMaxCommandWords = 256;
inline constexpr std::size_t kMaxCommandBytes = 16384;

}  // namespace parksim
