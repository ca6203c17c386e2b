#include "parksim/cli/FiguresOption.h"

#include "parksim/core/io/Error.h"
#include "parksim/renders/plots/FigureSelection.h"

namespace parksim::cli {

CLI::Option* addFiguresOption(CLI::App& sub, std::string& text, const std::string& default_help) {
  return sub
      .add_option("--figures", text,
                  "figures to draw into OUT/figures: all, none, or a comma-separated list of " +
                      figureNameList() + " (plan: every plan_*.png); " + default_help)
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            try {
              FigureSelection::parse(value);
            } catch (const Error& e) {
              return e.what();
            }
            return "";
          },
          "all|none|LIST"));
}

}  // namespace parksim::cli
