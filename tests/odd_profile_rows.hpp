#pragma once
// odd_profile.json's element rows (format 2, profile.hpp) turned back into
// one object per element, read here from the documented format and not
// through the library's reader, so that tests that look into the file check
// the format itself: "odd_element" and "id" from element_kinds, a null
// chainage from the s beside it, "point" and "reversed" from the flags.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace railodd::test {

template <class Json>
Json with_element_objects(Json doc) {
    if (!doc.contains("element_columns")) {
        return doc; // format 1 already
    }
    const auto& columns = doc["element_columns"];
    Json objects = Json::array();
    for (const auto& row : doc["elements"]) {
        Json e = Json::object();
        for (std::size_t i = 0; i < row.size(); ++i) {
            e[columns.at(i).template get<std::string>()] = row[i];
        }
        const auto& kind = doc["element_kinds"].at(e["kind"].template get<std::size_t>());
        e["odd_element"] = kind.at(0);
        e["id"] = kind.at(1);
        for (const char* end : {"start", "end"}) {
            const std::string c = std::string{"chainage_"} + end;
            if (e[c].is_null()) {
                e[c] = e[std::string{"s_"} + end];
            }
        }
        const Json flags = e.contains("flags") ? e["flags"] : Json::array();
        e["point"] = std::find(flags.begin(), flags.end(), "point") != flags.end();
        if (std::find(flags.begin(), flags.end(), "reversed") != flags.end()) {
            e["reversed"] = true;
        }
        objects.push_back(std::move(e));
    }
    doc["elements"] = std::move(objects);
    return doc;
}

} // namespace railodd::test
