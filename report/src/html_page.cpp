// The page: the template with the libraries, the app and the data inlined.
// Placeholders are replaced in one pass over the template, so text inside an
// inlined library that looks like a placeholder is left alone.
#include "railodd/report/report.hpp"

#include <map>
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
std::string script_json(const nlohmann::ordered_json& data) {
    const std::string text = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (c == '<') {
            out += "\\u003c";
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace

std::string render_html(const nlohmann::ordered_json& data) {
    const auto meta = data.value("meta", nlohmann::ordered_json::object());
    const std::map<std::string_view, std::string> values{
        {"TITLE", html_escaped(meta.value("title", std::string{"railodd report"}))},
        {"VERSION", html_escaped(meta.value("railodd", std::string{}))},
        {"DATA", script_json(data)},
        {"LEAFLET_CSS", std::string{assets::leaflet_css}},
        {"UPLOT_CSS", std::string{assets::uplot_css}},
        {"APP_CSS", std::string{assets::app_css}},
        {"LEAFLET_JS", std::string{assets::leaflet_js}},
        {"UPLOT_JS", std::string{assets::uplot_js}},
        {"APP_JS", std::string{assets::app_js}},
    };
    const std::string_view t = assets::template_html;
    std::string page;
    std::size_t pos = 0;
    while (pos < t.size()) {
        const std::size_t at = t.find('@', pos);
        const std::size_t end = at == std::string_view::npos ? at : t.find('@', at + 1);
        if (end == std::string_view::npos) {
            page.append(t.substr(pos));
            break;
        }
        const auto it = values.find(t.substr(at + 1, end - at - 1));
        if (it == values.end()) {
            page.append(t.substr(pos, end - pos)); // a lone '@': keep it, look again from the next one
            pos = end;
            continue;
        }
        page.append(t.substr(pos, at - pos));
        page.append(it->second);
        pos = end + 1;
    }
    return page;
}

} // namespace railodd::report
