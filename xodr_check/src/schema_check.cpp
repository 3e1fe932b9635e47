// XSD validation by the reference tools rather than a schema engine of our
// own: xmllint (XSD 1.0) for OpenDRIVE 1.6 / 1.7, Python's xmlschema for 1.8,
// whose schema uses XSD 1.1 type alternatives that libxml2 cannot read.
#include "process.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/xodr_check/check.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace railodd::xodr_check {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kept_lines = 20;

// Prints "path: reason" per error and exits 1 when there are errors; 2 when
// the schema itself does not load, 3 when the module is missing.
const char* const xmlschema_script = R"PY(
import sys
try:
    import xmlschema
except ImportError:
    print("python3 has no xmlschema module (apt-get install python3-xmlschema)")
    sys.exit(3)
try:
    schema = xmlschema.XMLSchema11(sys.argv[1])
except Exception as e:
    print("schema does not load: %s" % str(e).splitlines()[0])
    sys.exit(2)
n = 0
for e in schema.iter_errors(sys.argv[2]):
    n += 1
    if n <= 20:
        reason = (e.reason or str(e)).splitlines()
        print("%s: %s" % (e.path, reason[0] if reason else "invalid"))
print("errors: %d" % n)
sys.exit(1 if n else 0)
)PY";

std::string core_schema_name(const std::string& version) {
    if (version == "1.6") {
        return "opendrive_16_core.xsd";
    }
    if (version == "1.7") {
        return "opendrive_17_core.xsd";
    }
    if (version == "1.8") {
        return "OpenDRIVE_Core.xsd";
    }
    throw UsageError("--xsd-dir", "no OpenDRIVE core schema is known for revision " + version + " (1.6, 1.7, 1.8)");
}

// DIR/NAME, else the first NAME below DIR in path order (so the schemas
// folder holding OpenDRIVE_1.6/, _1.7/, _1.8/ works as well).
fs::path find_core_schema(const fs::path& dir, const std::string& name) {
    if (!fs::is_directory(dir)) {
        throw UsageError(dir.string(), "--xsd-dir is not a directory");
    }
    if (fs::is_regular_file(dir / name)) {
        return dir / name;
    }
    std::vector<fs::path> found;
    for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied);
         it != fs::recursive_directory_iterator(); ++it) {
        if (it.depth() > 3) {
            it.disable_recursion_pending();
        } else if (it->is_regular_file() && it->path().filename() == name) {
            found.push_back(it->path());
        }
    }
    if (found.empty()) {
        throw UsageError(dir.string(), "no " + name + " in --xsd-dir or below it");
    }
    std::sort(found.begin(), found.end());
    return found.front();
}

void keep(SchemaResult& r, const std::string& line) {
    ++r.error_count;
    if (r.errors.size() < kept_lines) {
        r.errors.push_back(line);
    }
}

void run_xmllint(SchemaResult& r, const fs::path& file) {
    if (!find_program("xmllint")) {
        throw UsageError("--xsd-dir", "xmllint is not on PATH (apt-get install libxml2-utils)");
    }
    const ProcessOutput out = run_process({"xmllint", "--noout", "--schema", r.xsd, file.string()});
    r.validator = "xmllint --noout --schema " + r.xsd + " " + file.string();
    if (out.exit_code != 0 && out.exit_code != 3) {
        std::string first = out.lines.empty() ? "exit code " + std::to_string(out.exit_code) : out.lines.front();
        throw UsageError(r.xsd, "xmllint could not validate with this schema: " + first);
    }
    r.ran = true;
    r.valid = out.exit_code == 0;
    for (const auto& line : out.lines) {
        if (line.ends_with(" validates") || line.ends_with(" fails to validate")) {
            continue;
        }
        keep(r, line);
    }
}

void run_xmlschema(SchemaResult& r, const fs::path& file) {
    // Debian's python3-xmlschema is installed for /usr/bin/python3; a python3
    // earlier on PATH (pyenv, venv) usually lacks it.
    const std::string python = find_program("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const ProcessOutput out = run_process({python, "-c", xmlschema_script, r.xsd, file.string()});
    r.validator = python + " -c 'xmlschema.XMLSchema11(core).validate(file)' " + r.xsd + " " + file.string();
    if (out.exit_code != 0 && out.exit_code != 1) {
        std::string first = out.lines.empty() ? "exit code " + std::to_string(out.exit_code) : out.lines.front();
        throw UsageError(r.xsd, "python3 xmlschema could not validate: " + first);
    }
    r.ran = true;
    r.valid = out.exit_code == 0;
    for (const auto& line : out.lines) {
        if (line.rfind("errors: ", 0) == 0) {
            r.error_count = std::stoul(line.substr(8));
        } else if (r.errors.size() < kept_lines) {
            r.errors.push_back(line);
        }
    }
}

} // namespace

SchemaResult validate_schema(const fs::path& file, const std::string& version, const fs::path& xsd_dir) {
    SchemaResult r;
    // Canonical: libxml2 keys included schemas by path, and a "/a/../b" path to
    // the core schema makes the sub-schemas' include of it look like a second,
    // conflicting copy ("global element declaration already exists").
    r.xsd = fs::canonical(find_core_schema(xsd_dir, core_schema_name(version))).string();
    if (version == "1.8") {
        run_xmlschema(r, file);
    } else {
        run_xmllint(r, file);
    }
    return r;
}

} // namespace railodd::xodr_check
