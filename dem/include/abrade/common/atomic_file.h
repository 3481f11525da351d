#pragma once
// Replacing a file so that a crash or a kill at any moment leaves either the old or the new
// content, never half of one: the text is written to PATH.tmp, checked, and renamed over PATH
// (rename is atomic on one file system).
#include <string>

namespace abrade::io
{
  /// Writes @p text to @p path as above; a failed write (a full disk) is a RunError naming the
  /// file, and the old content stays.
  void write_file_atomically(const std::string &path, const std::string &text);
} // namespace abrade::io
