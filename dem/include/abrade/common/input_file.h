#pragma once
// The one check every input file passes before anything opens it: it exists, it is a regular
// file (a directory, a FIFO, a device such as /dev/zero or a socket is named for what it is, not
// "not found"), it is not a loop of symbolic links, and it can be read. Without it a FIFO blocks
// a reader forever, /dev/zero feeds it without end, and std::filesystem's own exception for a
// link loop reached the user as an internal error.
//
//   io::require_input_file(path);            // throws InputError(path, "is a directory ...")
//   io::require_input_file(path, "scan");    // "...: the scan is a directory"
#include <string>

namespace abrade::io
{
  /// Throws InputError naming @p path when it is not a readable regular file; @p what names the
  /// role of the file in the message ("parameter file", "scan"), "" for none.
  void require_input_file(const std::string &path, const std::string &what = "");
} // namespace abrade::io
