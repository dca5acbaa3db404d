// file checks for the tools' parsers that never throw: std::filesystem's
// throwing overloads end the program on a path the OS refuses (a name too
// long, a loop of links), and a user's file names are input like any other
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

namespace pathcheck {

// "" when p is a regular file, else why not (missing, or the OS's reason)
inline std::string whyNotAFile(const std::filesystem::path& p) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(p, ec)) return "";
  if (ec && ec != std::errc::no_such_file_or_directory) return "cannot be looked up: " + ec.message();
  return "not found";
}

// absolute, normalised form of p; p itself when the OS cannot say
inline std::string absolutePath(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::path a = std::filesystem::absolute(p, ec);
  return (ec ? p : a).lexically_normal().string();
}

}  // namespace pathcheck
