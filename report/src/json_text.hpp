#pragma once
// JSON text written straight into a string. The report's large arrays (road
// vertices, profile rows, node figures) took about ten times their text as an
// ordered_json tree: 286 MB more at the peak of a Cologne convert.
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::report::detail {

class JsonText {
public:
    explicit JsonText(std::string& out) : out_(out) {}

    JsonText& open(char bracket) {
        comma();
        out_ += bracket;
        first_.push_back(true);
        return *this;
    }
    JsonText& close(char bracket) {
        out_ += bracket;
        first_.pop_back();
        return *this;
    }
    JsonText& key(std::string_view k) {
        comma();
        append_string(k);
        out_ += ':';
        after_key_ = true;
        return *this;
    }
    // Shortest text that reads back as the same double; non-finite as null.
    JsonText& number(double v) {
        comma();
        if (!std::isfinite(v)) {
            out_ += "null";
            return *this;
        }
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, static_cast<std::size_t>(r.ptr - buf));
        return *this;
    }
    JsonText& integer(long long v) {
        comma();
        char buf[24];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, static_cast<std::size_t>(r.ptr - buf));
        return *this;
    }
    JsonText& string(std::string_view s) {
        comma();
        append_string(s);
        return *this;
    }
    JsonText& boolean(bool b) {
        comma();
        out_ += b ? "true" : "false";
        return *this;
    }
    // Text that is already JSON (a value built apart).
    JsonText& raw(std::string_view json) {
        comma();
        out_ += json;
        return *this;
    }
    // A small value built as a tree.
    JsonText& value(const nlohmann::ordered_json& j) {
        comma();
        out_ += j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        return *this;
    }
    template <typename T>
    JsonText& integers(const std::vector<T>& v) {
        open('[');
        for (const T x : v) integer(static_cast<long long>(x));
        return close(']');
    }
    JsonText& numbers(const std::vector<double>& v) {
        open('[');
        for (const double x : v) number(x);
        return close(']');
    }

private:
    void comma() {
        if (after_key_) {
            after_key_ = false;
            return;
        }
        if (!first_.empty()) {
            if (!first_.back()) {
                out_ += ',';
            }
            first_.back() = false;
        }
    }
    void append_string(std::string_view s) {
        out_ += nlohmann::ordered_json(std::string{s}).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }

    std::string& out_;
    std::vector<bool> first_; // per open container: nothing in it yet
    bool after_key_ = false;
};

} // namespace railodd::report::detail
