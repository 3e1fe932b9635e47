#include "railodd/util/json_shape.hpp"

#include "railodd/util/errors.hpp"

#include <string_view>

namespace railodd {

namespace {

using ojson = nlohmann::ordered_json;

bool is_kind(const ojson& v, JsonKind k) {
    switch (k) {
    case JsonKind::string: return v.is_string();
    case JsonKind::number: return v.is_number();
    case JsonKind::integer: return v.is_number_integer();
    case JsonKind::boolean: return v.is_boolean();
    case JsonKind::array: return v.is_array();
    case JsonKind::object: return v.is_object();
    }
    return false;
}

const char* kind_name(JsonKind k) {
    switch (k) {
    case JsonKind::string: return "a string";
    case JsonKind::number: return "a number";
    case JsonKind::integer: return "an integer";
    case JsonKind::boolean: return "true or false";
    case JsonKind::array: return "an array";
    case JsonKind::object: return "an object";
    }
    return "";
}

std::vector<std::string> keys_of(const std::string& path) {
    std::vector<std::string> keys;
    std::size_t start = 0;
    for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1) {
        keys.push_back(path.substr(start, slash - start));
    }
    keys.push_back(path.substr(start));
    return keys;
}

struct Walk {
    const JsonField& field;
    const std::vector<std::string>& keys;
    const std::filesystem::path& file;

    void fail(const std::string& at, const std::string& found) const {
        throw InputError(file.string(), at + ": expected " + kind_name(field.kind) + ", found " + found);
    }

    void check(const ojson& v, std::size_t k, const std::string& at) const {
        if (k == keys.size()) {
            if (!is_kind(v, field.kind)) {
                std::string text = v.dump();
                fail(at, std::string{v.type_name()} + " " + (text.size() > 40 ? text.substr(0, 40) + "..." : text));
            }
            return;
        }
        if (keys[k] == "*") {
            if (v.is_array()) {
                for (std::size_t i = 0; i < v.size(); ++i) {
                    check(v[i], k + 1, at + "/" + std::to_string(i));
                }
            }
            return;
        }
        if (!v.is_object()) {
            return; // the parent's own field says what it must be
        }
        const auto it = v.find(keys[k]);
        if (it == v.end() || (it->is_null() && !field.required)) {
            if (field.required && k + 1 == keys.size()) {
                fail(at + "/" + keys[k], "nothing (missing)");
            }
            return;
        }
        check(*it, k + 1, at + "/" + keys[k]);
    }
};

} // namespace

void require_shape(const ojson& root, const std::vector<JsonField>& fields, const std::filesystem::path& file) {
    for (const auto& f : fields) {
        const std::vector<std::string> keys = keys_of(f.path);
        Walk{f, keys, file}.check(root, 0, "");
    }
}

} // namespace railodd
