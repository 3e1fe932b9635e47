// Coordinates written with an exponent in OSM XML and OPL: libosmium 2.18
// overflows a signed integer on large ones (found by fuzz_convert); railodd
// refuses them before libosmium reads the file, and reads the harmless ones.
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/util/errors.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace railodd::ingest;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

const std::string track_tail = "<way id=\"10\" version=\"1\"><nd ref=\"1\"/><nd ref=\"2\"/><nd ref=\"3\"/>"
                               "<tag k=\"railway\" v=\"rail\"/></way>\n</osm>\n";

std::string xml(const std::string& first_lat, const std::string& extra = "") {
    return "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n" + extra + "<node id=\"1\" version=\"1\" lat=\"" + first_lat +
           "\" lon=\"10.0\"/>\n<node id=\"2\" version=\"1\" lat=\"48.0\" lon=\"10.001\"/>\n"
           "<node id=\"3\" version=\"1\" lat=\"48.0\" lon=\"10.002\"/>\n" + track_tail;
}

// The problem read_osm refuses `file` with; empty when it reads it.
std::string refusal(const std::filesystem::path& file) {
    try {
        (void)read_osm(file, {});
    } catch (const railodd::InputError& e) {
        EXPECT_EQ(e.where(), file.string());
        return e.problem();
    }
    return {};
}

} // namespace

// The fuzzer's input, decoded: an OPL node at x = 199 * 10^9999.
TEST(IngestTextCoordinates, TheFuzzFindingIsRefusedNamingTheLineAndValue) {
    const auto dir = scratch_dir();
    const auto f = write_file(dir / "finding.opl", "n1 v1 x199e9999 y48.0\nn3 v1 x10.0 y48.0\n"
                                                   "w1 v1 Tmaxspeed=100 Nn1,n2,n3\n");
    const std::string p = refusal(f);
    EXPECT_NE(p.find("line 1"), std::string::npos) << p;
    EXPECT_NE(p.find("x199e9999"), std::string::npos) << p;
    EXPECT_NE(p.find("exponent"), std::string::npos) << p;
}

// The second finding (CI's 60-second run): the same exponent followed by a
// letter and 300 NUL bytes. libosmium scales the number before it finds the
// trailing bytes, so a value too long to keep must still be checked.
TEST(IngestTextCoordinates, TrailingBytesDoNotHideTheExponent) {
    const auto dir = scratch_dir();
    std::string text = "n1 v1 x199e999l";
    text.append(300, '\0');
    text += " y48.0\n";
    const std::string p = refusal(write_file(dir / "trailing.opl", text));
    EXPECT_NE(p.find("line 1"), std::string::npos) << p;
    EXPECT_NE(p.find("x199e999l\\x00"), std::string::npos) << p;
    EXPECT_NE(p.find("exponent"), std::string::npos) << p;
    EXPECT_NE(refusal(write_file(dir / "trailing.osm", "<osm version=\"0.6\"><node id=\"1\" version=\"1\" "
                                                       "lat=\"1e20x" + std::string(300, 'y') +
                                                       "\" lon=\"10\"/></osm>\n"))
                  .find("exponent"),
              std::string::npos);
}

TEST(IngestTextCoordinates, LargeExponentsAreRefusedInEveryPlaceACoordinateIs) {
    const auto dir = scratch_dir();
    EXPECT_NE(refusal(write_file(dir / "lat.osm", xml("1e20"))).find("line 3: coordinate lat=\"1e20"), std::string::npos);
    EXPECT_NE(refusal(write_file(dir / "single.osm", xml("48.0", "<bounds minlat='-4E15' minlon='9' maxlat='49' maxlon='11'/>\n")))
                  .find("minlat='-4E15"),
              std::string::npos);
    // A way's node list with locations (OPL), and a y field.
    EXPECT_NE(refusal(write_file(dir / "nodes.opl", "n1 v1 x10.0 y48.0\nn2 v1 x10.001 y48.0\n"
                                                    "w1 v1 Trailway=rail Nn1x10.0y4.8e30,n2x10.001y48.0\n"))
                  .find("y4.8e30"),
              std::string::npos);
    EXPECT_NE(refusal(write_file(dir / "y.opl", "n1 v1 x10.0 y9.9e99\n")).find("line 1: coordinate y9.9e99"),
              std::string::npos);
    // Compressed files are read through the same decompression libosmium uses.
    const auto plain = write_file(dir / "big.osm", xml("2.5e300"));
    ASSERT_EQ(std::system(("gzip -kf '" + plain.string() + "'").c_str()), 0);
    EXPECT_NE(refusal(dir / "big.osm.gz").find("2.5e300"), std::string::npos);
}

TEST(IngestTextCoordinates, HarmlessExponentsAndLookalikesAreRead) {
    const auto dir = scratch_dir();
    // 4.8e1 is 48: read as such, the same track as the plain file.
    const IngestResult e = read_osm(write_file(dir / "e.osm", xml("4.8e1")), {});
    const IngestResult plain = read_osm(write_file(dir / "plain.osm", xml("48.0")), {});
    ASSERT_EQ(e.tracks.size(), 1u);
    ASSERT_EQ(plain.tracks.size(), 1u);
    ASSERT_EQ(e.tracks[0].parts.size(), 1u);
    ASSERT_EQ(plain.tracks[0].parts.size(), 1u);
    ASSERT_EQ(e.tracks[0].parts[0].size(), 3u);
    ASSERT_EQ(plain.tracks[0].parts[0].size(), 3u);
    EXPECT_EQ(e.tracks[0].parts[0][0].lonlat.lat, 48.0);
    EXPECT_EQ(e.tracks[0].parts[0][0].xy.x, plain.tracks[0].parts[0][0].xy.x);
    EXPECT_EQ(e.tracks[0].parts[0][0].xy.y, plain.tracks[0].parts[0][0].xy.y);
    // Tiny and negative exponents, zero with a huge one: nothing to overflow.
    EXPECT_EQ(refusal(write_file(dir / "small.osm", xml("4800000e-5"))), "");
    EXPECT_EQ(refusal(write_file(dir / "zero.osm", xml("48.0", "<node id=\"9\" version=\"1\" lat=\"0e99999\" lon=\"0\"/>\n"))), "");
    // Not coordinates: tag values, comments, OPL tag values starting with x.
    EXPECT_EQ(refusal(write_file(dir / "tags.osm", xml("48.0", "<!-- lat=\"1e99\" -->\n<node id=\"8\" version=\"1\" "
                                                               "lat=\"48.0\" lon=\"10.0\"><tag k=\"lat\" v=\"1e99\"/></node>\n"))),
              "");
    EXPECT_EQ(refusal(write_file(dir / "tags.opl", "n1 v1 x10.0 y48.0 Tref=x1e99,note=y5e50\nn2 v1 x10.001 y48.0\n"
                                                   "n3 v1 x10.002 y48.0\nw1 v1 Trailway=rail Nn1,n2,n3\n")),
              "");
}
