#include "parksim/cli/ReportFileOption.h"

#include <filesystem>

namespace parksim::cli {

CLI::Option* addReportFileOption(CLI::App& sub, const std::string& name, std::string& path,
                                 const std::string& help) {
  return sub.add_option(name, path, help)
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            namespace fs = std::filesystem;
            std::error_code ec;
            if (value.empty()) return "a file name is needed";
            if (fs::is_directory(value, ec)) return value + ": is a directory, not a file";
            fs::path folder = fs::path(value).parent_path();
            if (folder.empty()) folder = ".";
            if (!fs::is_directory(folder, ec)) {
              return value + ": folder " + folder.string() + " does not exist";
            }
            return "";
          },
          "FILE"));
}

}  // namespace parksim::cli
