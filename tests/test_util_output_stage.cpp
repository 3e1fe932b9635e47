// OutputStage: outputs appear in the output folder only when the command
// commits, streamed or whole, and a writer that fails leaves nothing behind.
#include "railodd/util/output_stage.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <future>
#include <ostream>
#include <stdexcept>

using namespace railodd;
using railodd::test::scratch_dir;

namespace {

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::size_t entries(const std::filesystem::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) {
        ++n;
    }
    return n;
}

} // namespace

TEST(OutputStage, StreamedAndWholeOutputsAppearOnlyOnCommit) {
    const auto out = scratch_dir() / "out";
    {
        OutputStage stage(out);
        stage.write_with("big.txt", [](std::ostream& o) {
            for (int i = 0; i < 100000; ++i) {
                o << i << '\n';
            }
        });
        stage.write_text("sub/small.txt", "small\n");
        EXPECT_FALSE(std::filesystem::exists(out / "big.txt"));
        EXPECT_EQ(stage.commit().size(), 2u);
    }
    const std::string big = read(out / "big.txt");
    EXPECT_EQ(big.substr(0, 6), "0\n1\n2\n");
    EXPECT_EQ(big.size(), 588890u); // the digits of 0..99999 plus one newline each
    EXPECT_EQ(read(out / "sub" / "small.txt"), "small\n");
    EXPECT_EQ(entries(out), 2u); // big.txt and sub/: the staging folder is gone
}

TEST(OutputStage, AFailingWriterLeavesNoOutput) {
    const auto out = scratch_dir() / "out";
    {
        OutputStage stage(out);
        stage.write_text("first.txt", "ok\n");
        EXPECT_THROW(stage.write_with("second.txt",
                                      [](std::ostream& o) {
                                          o << "half";
                                          throw std::runtime_error("writer failed");
                                      }),
                     std::runtime_error);
    } // never committed
    EXPECT_EQ(entries(out), 0u);
}

TEST(OutputStage, WritersOnTwoThreadsCommitBothFiles) {
    const auto out = scratch_dir() / "out";
    OutputStage stage(out);
    auto other = std::async(std::launch::async, [&] {
        stage.write_with("a.txt", [](std::ostream& o) { o << std::string(1 << 20, 'a'); });
    });
    stage.write_with("b.txt", [](std::ostream& o) { o << std::string(1 << 20, 'b'); });
    other.get();
    EXPECT_EQ(stage.commit().size(), 2u);
    EXPECT_EQ(read(out / "a.txt"), std::string(1 << 20, 'a'));
    EXPECT_EQ(read(out / "b.txt"), std::string(1 << 20, 'b'));
}
