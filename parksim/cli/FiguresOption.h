#pragma once
// `--figures none|all|LIST` on the commands that draw figures (run, render).

#include <string>

#include <CLI/CLI.hpp>

namespace parksim::cli {

/// Adds `--figures none|all|LIST` to a figure-making command, storing the text in `text` (parse
/// it with FigureSelection::parse). An unknown name is a usage error (exit 2) whose one line
/// lists the valid names. `default_help` says what an absent option means.
CLI::Option* addFiguresOption(CLI::App& sub, std::string& text, const std::string& default_help);

}  // namespace parksim::cli
