#pragma once
// Input files named by the user: a directory, a device or a missing file is
// refused up front as an InputError naming the path, before a stream or a
// parser turns it into a low-level error ("basic_filebuf::underflow").
#include <filesystem>
#include <string>

namespace railodd {

// Throws InputError(path, "no such file (<what>)", "is a directory, not a
// file (<what>)", "not a regular file (...)" or "cannot be read (...)").
void require_input_file(const std::filesystem::path& path, const std::string& what);

// The whole file as bytes, after require_input_file.
std::string read_input_file(const std::filesystem::path& path, const std::string& what);

} // namespace railodd
