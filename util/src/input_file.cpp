#include "railodd/util/input_file.hpp"

#include "railodd/util/errors.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace railodd {

namespace fs = std::filesystem;

void require_input_file(const fs::path& path, const std::string& what) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (path.empty()) {
        throw InputError("''", "the file name is empty (" + what + ")");
    }
    if (!fs::exists(status)) {
        throw InputError(path.string(), "no such file (" + what + ")");
    }
    if (fs::is_directory(status)) {
        throw InputError(path.string(), "is a directory, not a file (" + what + ")");
    }
    if (!fs::is_regular_file(status)) {
        throw InputError(path.string(), "not a regular file (" + what + ")");
    }
    if (!std::ifstream(path, std::ios::binary)) {
        throw InputError(path.string(), "cannot be read (" + what + ")");
    }
}

std::string read_input_file(const fs::path& path, const std::string& what) {
    require_input_file(path, what);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) {
        throw InputError(path.string(), "read error (" + what + ")");
    }
    return std::move(text).str();
}

} // namespace railodd
