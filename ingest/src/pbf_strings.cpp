#include "pbf_strings.hpp"

#include "railodd/util/errors.hpp"

#include <protozero/exception.hpp>
#include <protozero/pbf_reader.hpp>
#include <protozero/varint.hpp>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railodd::ingest {

namespace {

// The limits of the PBF format (and libosmium's): larger sizes are damage
// that libosmium reports itself.
constexpr std::uint32_t max_blob_header = 64U * 1024U;
constexpr std::uint32_t max_blob = 32U * 1024U * 1024U;

// A data block's bytes, inflated only as far as asked: the string table is
// the block's first field, so most of a block is never inflated here.
class BlockBytes {
public:
    explicit BlockBytes(std::string_view raw) : raw_(raw), inflated_(raw.size()), done_(true) {}
    BlockBytes(std::string_view zlib, std::size_t raw_size) : raw_(zlib), out_(new char[raw_size]), size_(raw_size) {
        zs_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zlib.data()));
        zs_.avail_in = static_cast<uInt>(zlib.size());
        ok_ = inflateInit(&zs_) == Z_OK;
        done_ = !ok_;
    }
    BlockBytes(const BlockBytes&) = delete;
    BlockBytes& operator=(const BlockBytes&) = delete;
    ~BlockBytes() {
        if (out_ && ok_) {
            inflateEnd(&zs_);
        }
    }

    // The first `n` bytes of the block, or all there are.
    std::string_view prefix(std::size_t n) {
        while (!done_ && inflated_ < std::min(n, size_)) {
            zs_.next_out = reinterpret_cast<Bytef*>(out_.get() + inflated_);
            const std::size_t want = std::min(size_ - inflated_, std::max<std::size_t>(n - inflated_, 4096));
            zs_.avail_out = static_cast<uInt>(want);
            const int rc = inflate(&zs_, Z_SYNC_FLUSH);
            inflated_ += want - zs_.avail_out;
            done_ = rc != Z_OK || inflated_ == size_;
        }
        const char* base = out_ ? out_.get() : raw_.data();
        return {base, std::min(n, inflated_)};
    }
    std::string_view all() { return prefix(SIZE_MAX); }

private:
    std::string_view raw_;
    std::unique_ptr<char[]> out_;
    std::size_t size_ = 0;
    std::size_t inflated_ = 0;
    z_stream zs_{};
    bool ok_ = true;
    bool done_ = false;
};

std::string_view view(protozero::data_view v) { return {v.data(), v.size()}; }

// Indices of the string table's strings that hold a NUL byte.
std::vector<std::uint32_t> strings_with_nul(std::string_view table) {
    std::vector<std::uint32_t> bad;
    protozero::pbf_reader st{table.data(), table.size()};
    std::uint32_t index = 0;
    while (st.next()) {
        if (st.tag() != 1) {
            st.skip();
            continue;
        }
        const auto s = st.get_view();
        if (std::memchr(s.data(), '\0', s.size()) != nullptr) {
            bad.push_back(index);
        }
        ++index;
    }
    return bad;
}

// The string table of a PrimitiveBlock; usually its first field, so only
// that much of the block is inflated.
std::string_view string_table(BlockBytes& block) {
    const std::string_view head = block.prefix(16);
    const char* p = head.data();
    const char* end = head.data() + head.size();
    if (head.empty() || protozero::decode_varint(&p, end) != ((1U << 3U) | 2U)) {
        const std::string_view all = block.all();
        protozero::pbf_reader msg{all.data(), all.size()};
        return msg.next(1) ? view(msg.get_view()) : std::string_view{};
    }
    const auto length = protozero::decode_varint(&p, end);
    const auto offset = static_cast<std::size_t>(p - head.data());
    const std::string_view whole = block.prefix(offset + length);
    return whole.size() == offset + length ? whole.substr(offset) : std::string_view{};
}

struct Use {
    const char* type;
    std::int64_t id;
    const char* what;
};

bool is_bad(const std::vector<std::uint32_t>& bad, std::uint64_t index) {
    return std::binary_search(bad.begin(), bad.end(), index);
}

// Keys (field 2), values (3) and, for relations, member roles (8) of a Node,
// Way or Relation message.
std::optional<Use> use_in_object(protozero::pbf_reader obj, const char* type, bool zigzag_id, bool roles,
                                 const std::vector<std::uint32_t>& bad) {
    std::int64_t id = 0;
    const char* what = nullptr;
    while (obj.next()) {
        if (obj.tag() == 1 && obj.wire_type() == protozero::pbf_wire_type::varint) {
            id = zigzag_id ? obj.get_sint64() : obj.get_int64();
        } else if ((obj.tag() == 2 || obj.tag() == 3) && obj.wire_type() == protozero::pbf_wire_type::length_delimited) {
            const char* name = obj.tag() == 2 ? "tag key" : "tag value";
            for (const auto i : obj.get_packed_uint32()) {
                what = !what && is_bad(bad, i) ? name : what;
            }
        } else if (roles && obj.tag() == 8 && obj.wire_type() == protozero::pbf_wire_type::length_delimited) {
            for (const auto i : obj.get_packed_int32()) {
                what = !what && i >= 0 && is_bad(bad, static_cast<std::uint64_t>(i)) ? "member role" : what;
            }
        } else {
            obj.skip();
        }
    }
    return what ? std::optional<Use>{Use{type, id, what}} : std::nullopt;
}

// DenseNodes: delta-coded ids (field 1) and keys_vals (10), each node's
// key/value indices closed by a 0.
std::optional<Use> use_in_dense(protozero::pbf_reader dense, const std::vector<std::uint32_t>& bad) {
    std::vector<std::int64_t> ids;
    std::vector<std::int32_t> keys_vals;
    while (dense.next()) {
        if (dense.tag() == 1 && dense.wire_type() == protozero::pbf_wire_type::length_delimited) {
            std::int64_t id = 0;
            for (const auto d : dense.get_packed_sint64()) {
                ids.push_back(id += d);
            }
        } else if (dense.tag() == 10 && dense.wire_type() == protozero::pbf_wire_type::length_delimited) {
            for (const auto kv : dense.get_packed_int32()) {
                keys_vals.push_back(kv);
            }
        } else {
            dense.skip();
        }
    }
    std::size_t node = 0;
    bool key = true;
    for (const auto kv : keys_vals) {
        if (kv == 0 && key) {
            ++node;
            continue;
        }
        if (kv > 0 && is_bad(bad, static_cast<std::uint64_t>(kv))) {
            return Use{"node", node < ids.size() ? ids[node] : 0, key ? "tag key" : "tag value"};
        }
        key = !key;
    }
    return std::nullopt;
}

// The first object of the block that uses one of the `bad` strings.
std::optional<Use> first_use(std::string_view block, const std::vector<std::uint32_t>& bad) {
    protozero::pbf_reader pb{block.data(), block.size()};
    while (pb.next()) {
        if (pb.tag() != 2 || pb.wire_type() != protozero::pbf_wire_type::length_delimited) {
            pb.skip();
            continue;
        }
        protozero::pbf_reader group = pb.get_message();
        while (group.next()) {
            std::optional<Use> use;
            switch (group.wire_type() == protozero::pbf_wire_type::length_delimited ? group.tag() : 0) {
            case 1: use = use_in_object(group.get_message(), "node", true, false, bad); break;
            case 2: use = use_in_dense(group.get_message(), bad); break;
            case 3: use = use_in_object(group.get_message(), "way", false, false, bad); break;
            case 4: use = use_in_object(group.get_message(), "relation", false, true, bad); break;
            default: group.skip(); break;
            }
            if (use) {
                return use;
            }
        }
    }
    return std::nullopt;
}

std::optional<std::uint32_t> read_be32(std::istream& in) {
    unsigned char b[4];
    if (!in.read(reinterpret_cast<char*>(b), 4)) {
        return std::nullopt;
    }
    return (std::uint32_t{b[0]} << 24U) | (std::uint32_t{b[1]} << 16U) | (std::uint32_t{b[2]} << 8U) | b[3];
}

struct Blob {
    std::string type;
    std::string bytes;
};

std::optional<Blob> read_blob(std::istream& in) {
    const auto header_size = read_be32(in);
    if (!header_size || *header_size > max_blob_header) {
        return std::nullopt;
    }
    std::string header(*header_size, '\0');
    if (!in.read(header.data(), static_cast<std::streamsize>(header.size()))) {
        return std::nullopt;
    }
    Blob blob;
    std::int32_t size = -1;
    protozero::pbf_reader h{header};
    while (h.next()) {
        if (h.tag() == 1 && h.wire_type() == protozero::pbf_wire_type::length_delimited) {
            blob.type = h.get_string();
        } else if (h.tag() == 3 && h.wire_type() == protozero::pbf_wire_type::varint) {
            size = h.get_int32();
        } else {
            h.skip();
        }
    }
    if (size < 0 || static_cast<std::uint32_t>(size) > max_blob) {
        return std::nullopt;
    }
    blob.bytes.resize(static_cast<std::size_t>(size));
    if (!in.read(blob.bytes.data(), size)) {
        return std::nullopt;
    }
    return blob;
}

// The NUL-holding string a data blob's objects use, if any.
std::optional<Use> check_blob(const std::string& blob) {
    std::string_view raw, zlib;
    std::int32_t raw_size = 0;
    protozero::pbf_reader b{blob};
    while (b.next()) {
        if (b.tag() == 1 && b.wire_type() == protozero::pbf_wire_type::length_delimited) {
            raw = view(b.get_view());
        } else if (b.tag() == 2 && b.wire_type() == protozero::pbf_wire_type::varint) {
            raw_size = b.get_int32();
        } else if (b.tag() == 3 && b.wire_type() == protozero::pbf_wire_type::length_delimited) {
            zlib = view(b.get_view());
        } else {
            b.skip(); // lzma, lz4, zstd: libosmium reads or refuses them
        }
    }
    std::optional<BlockBytes> block;
    if (!raw.empty()) {
        block.emplace(raw);
    } else if (!zlib.empty() && raw_size > 0 && static_cast<std::uint32_t>(raw_size) <= max_blob) {
        block.emplace(zlib, static_cast<std::size_t>(raw_size));
    } else {
        return std::nullopt;
    }
    const auto bad = strings_with_nul(string_table(*block));
    return bad.empty() ? std::nullopt : first_use(block->all(), bad);
}

} // namespace

void check_pbf_strings(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw InputError(file.string(), "cannot be read");
    }
    std::size_t data_block = 0;
    try {
        while (auto blob = read_blob(in)) {
            if (blob->type != "OSMData") {
                continue;
            }
            ++data_block;
            if (const auto use = check_blob(blob->bytes)) {
                throw InputError(file.string(), std::string{"OSM "} + use->type + " " + std::to_string(use->id) + ": " +
                                                    use->what + " holds a NUL byte (PBF data block " +
                                                    std::to_string(data_block) +
                                                    "); OSM text cannot contain one, the file is damaged");
            }
        }
    } catch (const protozero::exception&) {
        // Damaged framing or messages: libosmium's decoder reports it with its own words.
    }
}

} // namespace railodd::ingest
