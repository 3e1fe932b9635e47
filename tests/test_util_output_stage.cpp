// OutputStage: outputs appear in the output folder only when the command
// commits, streamed or whole, and a writer that fails leaves nothing behind.
#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <fstream>
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
    EXPECT_FALSE(std::filesystem::exists(out)); // the run made the folder: gone again
}

// A folder that was there before a failed run stays, with what it held; a
// scratch file is never moved into place, nor left behind.
TEST(OutputStage, AFailedRunLeavesAnExistingFolderAsItWas) {
    const auto out = scratch_dir() / "out";
    std::filesystem::create_directories(out);
    { std::ofstream(out / "earlier.txt") << "earlier\n"; }
    {
        OutputStage stage(out);
        stage.write_text("new.txt", "new\n");
        std::ofstream(stage.scratch_path("rows.tmp")) << "scratch\n";
    } // never committed
    EXPECT_EQ(entries(out), 1u);
    EXPECT_EQ(read(out / "earlier.txt"), "earlier\n");
    {
        OutputStage stage(out);
        std::ofstream(stage.scratch_path("rows.tmp")) << "scratch\n";
        stage.write_text("new.txt", "new\n");
        EXPECT_EQ(stage.commit().size(), 1u);
    }
    EXPECT_EQ(entries(out), 2u); // earlier.txt and new.txt: no scratch, no staging folder
    EXPECT_EQ(read(out / "new.txt"), "new\n");
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

// Staging folders of killed runs (SIGKILL leaves them) are removed by the next
// run into the folder; other hidden files are not touched.
TEST(OutputStage, StagingLeftByAKilledRunIsRemoved) {
    const auto out = scratch_dir() / "out";
    std::filesystem::create_directories(out / ".railodd-staging-999999999" / "sub");
    test::write_file(out / ".railodd-staging-999999999" / "sub" / "map.xodr", "half");
    test::write_file(out / ".keep", "user's");
    {
        OutputStage stage(out);
        stage.write_text("a.txt", "A");
        stage.commit();
    }
    EXPECT_FALSE(std::filesystem::exists(out / ".railodd-staging-999999999"));
    EXPECT_EQ(read(out / ".keep"), "user's");
    EXPECT_EQ(entries(out), 2u);
}

// A run killed between its journal and its last rename: the next run into
// the folder finishes that commit first (roll forward), so the folder never
// stays a mix of the old and the new run.
TEST(OutputStage, CommitInterruptedAfterItsJournalIsRolledForward) {
    const auto out = scratch_dir() / "out";
    const auto staging = out / ".railodd-staging-12345";
    std::filesystem::create_directories(staging);
    test::write_file(out / "a.txt", "old A");
    test::write_file(out / "b.txt", "new B"); // already moved before the kill
    test::write_file(out / "gone.txt", "stale");
    test::write_file(staging / "a.txt", "new A");
    test::write_file(out / ".railodd-journal", ".railodd-staging-12345\n+ a.txt\n+ b.txt\n- gone.txt\n");
    {
        OutputStage stage(out);
        EXPECT_EQ(read(out / "a.txt"), "new A");
        EXPECT_EQ(read(out / "b.txt"), "new B");
        EXPECT_FALSE(std::filesystem::exists(out / "gone.txt"));
        EXPECT_FALSE(std::filesystem::exists(out / ".railodd-journal"));
        EXPECT_FALSE(std::filesystem::exists(staging));
    }
}

TEST(OutputStage, ASecondRunIntoTheSameFolderIsRefused) {
    const auto out = scratch_dir() / "out";
    OutputStage first(out);
    try {
        OutputStage second(out);
        FAIL() << "two stages locked one folder";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string{e.what()}.find("another railodd run"), std::string::npos) << e.what();
    }
    first.write_text("a.txt", "A");
    first.commit();
    EXPECT_EQ(read(out / "a.txt"), "A");
}

TEST(OutputStage, RemovalsHappenInTheCommitUnlessWrittenAgain) {
    const auto out = scratch_dir() / "out";
    std::filesystem::create_directories(out / "distributions");
    test::write_file(out / "old.xosc", "old");
    test::write_file(out / "kept.xosc", "old kept");
    test::write_file(out / "distributions" / "old.xosc", "old");
    OutputStage stage(out);
    stage.write_text("kept.xosc", "new kept");
    stage.remove_on_commit("old.xosc");
    stage.remove_on_commit("kept.xosc");
    stage.remove_on_commit("distributions/old.xosc");
    EXPECT_TRUE(std::filesystem::exists(out / "old.xosc")) << "nothing is removed before the commit";
    stage.commit();
    EXPECT_FALSE(std::filesystem::exists(out / "old.xosc"));
    EXPECT_FALSE(std::filesystem::exists(out / "distributions" / "old.xosc"));
    EXPECT_EQ(read(out / "kept.xosc"), "new kept");
}

TEST(OutputStage, NamesOutsideTheFolderAreRefused) {
    const auto dir = scratch_dir();
    OutputStage stage(dir / "out");
    for (const std::string name : {"../x.txt", "/tmp/x.txt", "a/../../x.txt", ".", "", "sub/"}) {
        EXPECT_THROW(stage.write_text(name, "x"), InputError) << name;
        EXPECT_THROW(stage.remove_on_commit(name), InputError) << name;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "x.txt"));
}

// A commit whose move cannot succeed (the name is a folder there) fails the
// run, and leaves neither journal nor staging: no later run into the folder
// is stopped by it.
TEST(OutputStage, ACommitThatCannotMoveLeavesNoJournal) {
    const auto out = scratch_dir() / "out";
    std::filesystem::create_directories(out / "page.html");
    {
        OutputStage stage(out);
        stage.write_text("page.html", "<html/>");
        EXPECT_THROW(stage.commit(), OutputError);
    }
    EXPECT_FALSE(std::filesystem::exists(out / ".railodd-journal"));
    EXPECT_EQ(entries(out), 1u); // page.html/ only: no staging folder
    OutputStage later(out);
    later.write_text("other.html", "<html/>");
    EXPECT_EQ(later.commit().size(), 1u);
}

// A folder another command only reads: the commit a killed run left there is
// finished before the reader looks, not after.
TEST(OutputStage, AReaderFinishesAPendingCommitFirst) {
    const auto dir = scratch_dir() / "set";
    const auto staging = dir / ".railodd-staging-12345";
    std::filesystem::create_directories(staging);
    test::write_file(dir / "manifest.json", "old");
    test::write_file(staging / "manifest.json", "new");
    test::write_file(dir / ".railodd-journal", ".railodd-staging-12345\n+ manifest.json\n");
    finish_pending_commit(dir);
    EXPECT_EQ(read(dir / "manifest.json"), "new");
    EXPECT_FALSE(std::filesystem::exists(dir / ".railodd-journal"));
    EXPECT_FALSE(std::filesystem::exists(staging));
    finish_pending_commit(dir); // nothing pending: nothing changes
    EXPECT_EQ(read(dir / "manifest.json"), "new");
}
