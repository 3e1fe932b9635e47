#include "text_coordinates.hpp"

#include "railodd/util/errors.hpp"

#include <osmium/io/any_compression.hpp>
#include <osmium/io/detail/read_write.hpp>
#include <osmium/io/file.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace railodd::ingest {

namespace {

constexpr double max_degrees = 1000.0;
constexpr std::size_t max_value = 256; // kept of a value: libosmium reads at most ~40 bytes of a number

// The part of a coordinate that libosmium reads and scales: sign, digits,
// fraction, exponent. What follows (a stray letter, NUL bytes) fails its
// format check only after the scaling, so it must not hide the exponent.
std::string_view numeric_prefix(std::string_view v) {
    std::size_t i = 0;
    auto digits = [&] {
        while (i < v.size() && v[i] >= '0' && v[i] <= '9') {
            ++i;
        }
    };
    i += i < v.size() && (v[i] == '-' || v[i] == '+') ? 1 : 0;
    digits();
    if (i < v.size() && v[i] == '.') {
        ++i;
        digits();
    }
    if (i < v.size() && (v[i] == 'e' || v[i] == 'E')) {
        ++i;
        i += i < v.size() && (v[i] == '-' || v[i] == '+') ? 1 : 0;
        digits();
    }
    return v.substr(0, i);
}

// A value that libosmium would scale by its exponent past what an int64 holds.
bool unsafe_exponent(std::string_view v) {
    v = numeric_prefix(v);
    if (v.find_first_of("eE") == std::string_view::npos) {
        return false;
    }
    double d = 0.0;
    const auto r = std::from_chars(v.data(), v.data() + v.size(), d);
    if (r.ec == std::errc::result_out_of_range) {
        return v.find("e-") == std::string_view::npos && v.find("E-") == std::string_view::npos;
    }
    return r.ec == std::errc{} && !(std::abs(d) <= max_degrees);
}

// The value as it can be shown in a message: control bytes escaped.
std::string printable(std::string_view v) {
    std::string out;
    for (const char ch : v) {
        const auto u = static_cast<unsigned char>(ch);
        if (u < 0x20 || u == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", u);
            out += hex;
        } else {
            out += ch;
        }
    }
    return out;
}

// Common to both formats: the current coordinate's text, the line, and the
// refusal.
class Collector {
public:
    explicit Collector(const std::filesystem::path& file) : file_(file) {}
    void start(std::string label, std::string close = {}) {
        label_ = std::move(label);
        close_ = std::move(close);
        value_.clear();
        on_ = true;
    }
    void add(char c) {
        if (on_ && value_.size() < max_value) {
            value_ += c;
        }
    }
    void finish() {
        if (on_ && unsafe_exponent(value_)) { // the first max_value bytes hold all libosmium reads
            throw InputError(file_.string(), "line " + std::to_string(line_) + ": coordinate " + printable(label_ + value_ + close_) +
                                                 " has an exponent beyond any coordinate (over " +
                                                 std::to_string(static_cast<int>(max_degrees)) +
                                                 " degrees), which libosmium cannot read safely");
        }
        on_ = false;
    }
    void newline() noexcept { ++line_; }

private:
    std::filesystem::path file_;
    std::string label_; // what precedes the value: lat=" or x
    std::string close_; // and follows it: the quote
    std::string value_;
    bool on_ = false;
    long line_ = 1;
};

// XML: attribute values inside element tags; comments and declarations
// skipped. Attribute names are collected to tell *lat and *lon apart.
class XmlScan {
public:
    explicit XmlScan(Collector& c) : c_(c) {}
    void feed(char ch) {
        switch (state_) {
        case State::text: state_ = ch == '<' ? State::open : State::text; break;
        case State::open:
            state_ = std::isalpha(static_cast<unsigned char>(ch)) ? State::tag : ch == '!' ? State::bang : State::other;
            break;
        case State::bang: state_ = ch == '-' ? State::comment : State::other; break;
        case State::comment: comment(ch); break;
        case State::other: state_ = ch == '>' ? State::text : State::other; break;
        case State::tag: tag(ch); break;
        case State::value: value(ch); break;
        }
    }

private:
    enum class State { text, open, bang, comment, other, tag, value };
    void comment(char ch) {
        if (ch == '>' && dashes_ >= 2) {
            state_ = State::text;
        }
        dashes_ = ch == '-' ? dashes_ + 1 : 0;
    }
    void tag(char ch) {
        if (ch == '>') {
            state_ = State::text;
        } else if (ch == '"' || ch == '\'') {
            quote_ = ch;
            state_ = State::value;
            const bool coordinate = name_.ends_with("lat") || name_.ends_with("lon");
            if (coordinate) {
                c_.start(name_ + "=" + ch, std::string(1, ch));
            }
        } else if (ch == '=' || std::isspace(static_cast<unsigned char>(ch))) {
            name_done_ = true;
        } else {
            if (name_done_) {
                name_.clear();
                name_done_ = false;
            }
            if (name_.size() < 64) {
                name_ += ch;
            }
        }
    }
    void value(char ch) {
        if (ch == quote_) {
            c_.finish();
            state_ = State::tag;
            name_.clear();
            name_done_ = false;
        } else {
            c_.add(ch);
        }
    }
    Collector& c_;
    State state_ = State::text;
    std::string name_;
    bool name_done_ = false;
    char quote_ = '"';
    int dashes_ = 0;
};

// OPL: fields are separated by spaces, a field's first letter its kind; x
// and y fields are coordinates, and so are the x / y parts of a way's node
// list (N field: n12x1.5y2.5,n13...). Tag values are %-escaped, so no space
// or comma inside them.
class OplScan {
public:
    explicit OplScan(Collector& c) : c_(c) {}
    void feed(char ch) {
        if (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t') {
            c_.finish();
            field_start_ = true;
            kind_ = 0;
            return;
        }
        if (field_start_) {
            field_start_ = false;
            kind_ = ch;
            if (ch == 'x' || ch == 'y') {
                c_.start(std::string(1, ch));
            }
            return;
        }
        if (kind_ == 'N' && (ch == 'x' || ch == 'y' || ch == ',')) {
            c_.finish();
            if (ch != ',') {
                c_.start(std::string(1, ch));
            }
            return;
        }
        c_.add(ch);
    }

private:
    Collector& c_;
    bool field_start_ = true;
    char kind_ = 0;
};

template <class Scan>
void scan_file(const std::filesystem::path& file, osmium::io::file_compression compression) {
    Collector c(file);
    Scan scan(c);
    const int fd = osmium::io::detail::open_for_reading(file.string());
    auto in = osmium::io::CompressionFactory::instance().create_decompressor(compression, fd);
    for (std::string chunk = in->read(); !chunk.empty(); chunk = in->read()) {
        for (const char ch : chunk) {
            scan.feed(ch); // first: a value ends at the line's end, on that line
            if (ch == '\n') {
                c.newline();
            }
        }
    }
    c.finish();
    in->close();
}

} // namespace

void check_text_coordinates(const std::filesystem::path& file) {
    try {
// GCC 12 sees libosmium's File constructor compare its own just-built
// file name and calls it uninitialised (a false positive inside the header).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
        const osmium::io::File f{file.string()};
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
        const osmium::io::file_format format = f.format();
        if (format == osmium::io::file_format::xml) {
            scan_file<XmlScan>(file, f.compression());
        } else if (format == osmium::io::file_format::opl) {
            scan_file<OplScan>(file, f.compression());
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception&) {
        // Damaged compression and the like: libosmium's own pass reports it.
    }
}

} // namespace railodd::ingest
