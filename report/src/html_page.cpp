// The page: the template with the libraries, the app and the data inlined.
// Placeholders are replaced in one pass over the template, so text inside an
// inlined library that looks like a placeholder is left alone.
#include "railodd/report/report.hpp"

#include <map>
#include <ostream>
#include <sstream>
#include <string_view>

namespace railodd::report {

namespace assets {
extern const std::string_view template_html;
extern const std::string_view leaflet_js;
extern const std::string_view leaflet_css;
extern const std::string_view uplot_js;
extern const std::string_view uplot_css;
extern const std::string_view app_js;
extern const std::string_view app_css;
} // namespace assets

namespace {

std::string html_escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

// JSON inside <script>: a '<' only ever occurs inside a JSON string, where
// \u003c is the same character, so "</script>" in an OSM name cannot end the
// element.
void write_script_json(const std::string& json, std::ostream& out) {
    std::size_t from = 0;
    for (std::size_t at = json.find('<'); at != std::string::npos; at = json.find('<', from)) {
        out.write(json.data() + from, static_cast<std::streamsize>(at - from));
        out << "\\u003c";
        from = at + 1;
    }
    out.write(json.data() + from, static_cast<std::streamsize>(json.size() - from));
}

} // namespace

void write_html(const PageData& data, std::ostream& out) {
    const std::map<std::string_view, std::string_view> assets_by_name{
        {"LEAFLET_CSS", assets::leaflet_css}, {"UPLOT_CSS", assets::uplot_css}, {"APP_CSS", assets::app_css},
        {"LEAFLET_JS", assets::leaflet_js},   {"UPLOT_JS", assets::uplot_js},   {"APP_JS", assets::app_js},
    };
    const std::string title = html_escaped(data.title);
    const std::string_view t = assets::template_html;
    std::size_t pos = 0;
    while (pos < t.size()) {
        const std::size_t at = t.find('@', pos);
        const std::size_t end = at == std::string_view::npos ? at : t.find('@', at + 1);
        if (end == std::string_view::npos) {
            out << t.substr(pos);
            break;
        }
        const std::string_view name = t.substr(at + 1, end - at - 1);
        const auto it = assets_by_name.find(name);
        if (it == assets_by_name.end() && name != "DATA" && name != "TITLE" && name != "VERSION") {
            out << t.substr(pos, end - pos); // a lone '@': keep it, look again from the next one
            pos = end;
            continue;
        }
        out << t.substr(pos, at - pos);
        if (name == "DATA") {
            for (const auto& part : data.parts) {
                write_script_json(part, out);
            }
        } else if (name == "TITLE") {
            out << title;
        } else if (name == "VERSION") {
            out << "0.1.0";
        } else {
            out << it->second;
        }
        pos = end + 1;
    }
}

std::string render_html(const nlohmann::ordered_json& data) {
    PageData page{data.value("meta", nlohmann::ordered_json::object()).value("title", std::string{"railodd report"}),
                  {data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)}};
    std::ostringstream out;
    write_html(page, out);
    return out.str();
}

} // namespace railodd::report
