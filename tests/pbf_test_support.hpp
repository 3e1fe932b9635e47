#pragma once
// A tiny OSM PBF writer for tests that need byte-level control of a file's
// string table (NUL bytes, arbitrary bytes), which libosmium's writer never
// produces: one header blob and one data block of dense nodes, ways and
// relations, raw or zlib-compressed.
#include <protozero/pbf_writer.hpp>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace railodd::test {

struct PbfNode {
    std::int64_t id;
    double lon, lat;
    std::vector<std::pair<std::string, std::string>> tags;
};
struct PbfWay {
    std::int64_t id;
    std::vector<std::pair<std::string, std::string>> tags;
    std::vector<std::int64_t> refs;
};
struct PbfMember {
    int type; // 0 node, 1 way, 2 relation
    std::int64_t ref;
    std::string role;
};
struct PbfRelation {
    std::int64_t id;
    std::vector<std::pair<std::string, std::string>> tags;
    std::vector<PbfMember> members;
};

class PbfBuilder {
public:
    std::vector<PbfNode> nodes;
    std::vector<PbfWay> ways;
    std::vector<PbfRelation> relations;
    bool zlib = true;
    bool string_table_last = false; // the string table after the groups (legal, unusual)
    std::vector<std::string> unused_strings; // in the table, used by no object

    void write(const std::filesystem::path& path) {
        std::ofstream out(path, std::ios::binary);
        write_blob(out, "OSMHeader", header_block());
        write_blob(out, "OSMData", data_block());
        if (!out) {
            throw std::runtime_error("cannot write " + path.string());
        }
    }

private:
    std::vector<std::string> strings_{""};
    std::map<std::string, std::uint32_t> index_;

    std::uint32_t sid(const std::string& s) {
        const auto [it, added] = index_.emplace(s, static_cast<std::uint32_t>(strings_.size()));
        if (added) {
            strings_.push_back(s);
        }
        return it->second;
    }

    static std::string header_block() {
        std::string data;
        protozero::pbf_writer hb{data};
        hb.add_string(4, "OsmSchema-V0.6");
        hb.add_string(4, "DenseNodes");
        hb.add_string(16, "railodd-tests");
        return data;
    }

    std::string dense_group() {
        std::string group;
        protozero::pbf_writer g{group};
        std::string dense;
        protozero::pbf_writer d{dense};
        std::vector<std::int64_t> ids, lats, lons;
        std::vector<std::int32_t> kv;
        std::int64_t pid = 0, plat = 0, plon = 0;
        for (const auto& n : nodes) {
            const auto lat = static_cast<std::int64_t>(n.lat * 1e7 + (n.lat < 0 ? -0.5 : 0.5));
            const auto lon = static_cast<std::int64_t>(n.lon * 1e7 + (n.lon < 0 ? -0.5 : 0.5));
            ids.push_back(n.id - pid);
            lats.push_back(lat - plat);
            lons.push_back(lon - plon);
            pid = n.id, plat = lat, plon = lon;
            for (const auto& [k, v] : n.tags) {
                kv.push_back(static_cast<std::int32_t>(sid(k)));
                kv.push_back(static_cast<std::int32_t>(sid(v)));
            }
            kv.push_back(0);
        }
        d.add_packed_sint64(1, ids.begin(), ids.end());
        d.add_packed_sint64(8, lats.begin(), lats.end());
        d.add_packed_sint64(9, lons.begin(), lons.end());
        d.add_packed_int32(10, kv.begin(), kv.end());
        g.add_message(2, dense);
        return group;
    }

    template <class Object>
    void add_tags(protozero::pbf_writer& w, const Object& o) {
        std::vector<std::uint32_t> keys, vals;
        for (const auto& [k, v] : o.tags) {
            keys.push_back(sid(k));
            vals.push_back(sid(v));
        }
        w.add_packed_uint32(2, keys.begin(), keys.end());
        w.add_packed_uint32(3, vals.begin(), vals.end());
    }

    std::string way_group() {
        std::string group;
        protozero::pbf_writer g{group};
        for (const auto& way : ways) {
            std::string msg;
            protozero::pbf_writer w{msg};
            w.add_int64(1, way.id);
            add_tags(w, way);
            std::vector<std::int64_t> refs;
            std::int64_t prev = 0;
            for (const auto r : way.refs) {
                refs.push_back(r - prev);
                prev = r;
            }
            w.add_packed_sint64(8, refs.begin(), refs.end());
            g.add_message(3, msg);
        }
        return group;
    }

    std::string relation_group() {
        std::string group;
        protozero::pbf_writer g{group};
        for (const auto& rel : relations) {
            std::string msg;
            protozero::pbf_writer w{msg};
            w.add_int64(1, rel.id);
            add_tags(w, rel);
            std::vector<std::int32_t> roles, types;
            std::vector<std::int64_t> memids;
            std::int64_t prev = 0;
            for (const auto& m : rel.members) {
                roles.push_back(static_cast<std::int32_t>(sid(m.role)));
                memids.push_back(m.ref - prev);
                prev = m.ref;
                types.push_back(m.type);
            }
            w.add_packed_int32(8, roles.begin(), roles.end());
            w.add_packed_sint64(9, memids.begin(), memids.end());
            w.add_packed_int32(10, types.begin(), types.end());
            g.add_message(4, msg);
        }
        return group;
    }

    std::string data_block() {
        std::vector<std::string> groups;
        if (!nodes.empty()) groups.push_back(dense_group());
        if (!ways.empty()) groups.push_back(way_group());
        if (!relations.empty()) groups.push_back(relation_group());
        for (const auto& s : unused_strings) {
            sid(s);
        }
        std::string table;
        protozero::pbf_writer st{table};
        for (const auto& s : strings_) {
            st.add_bytes(1, s);
        }
        std::string block;
        protozero::pbf_writer b{block};
        if (!string_table_last) {
            b.add_message(1, table);
        }
        for (const auto& g : groups) {
            b.add_message(2, g);
        }
        if (string_table_last) {
            b.add_message(1, table);
        }
        return block;
    }

    void write_blob(std::ofstream& out, const std::string& type, const std::string& payload) {
        std::string blob;
        protozero::pbf_writer b{blob};
        if (zlib) {
            uLongf size = compressBound(static_cast<uLong>(payload.size()));
            std::string packed(size, '\0');
            if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size,
                          reinterpret_cast<const Bytef*>(payload.data()), static_cast<uLong>(payload.size()),
                          Z_DEFAULT_COMPRESSION) != Z_OK) {
                throw std::runtime_error("zlib compress2 failed");
            }
            packed.resize(size);
            b.add_int32(2, static_cast<std::int32_t>(payload.size()));
            b.add_bytes(3, packed);
        } else {
            b.add_bytes(1, payload);
        }
        std::string header;
        protozero::pbf_writer h{header};
        h.add_string(1, type);
        h.add_int32(3, static_cast<std::int32_t>(blob.size()));
        const auto n = static_cast<std::uint32_t>(header.size());
        const char be[4] = {static_cast<char>(n >> 24U), static_cast<char>(n >> 16U), static_cast<char>(n >> 8U),
                            static_cast<char>(n)};
        out.write(be, 4);
        out << header << blob;
    }
};

} // namespace railodd::test
