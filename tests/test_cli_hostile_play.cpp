// Hostile input to `railodd play`, through the real executable with a fake
// player (a shell script standing in for esmini, dat2csv and odrplot): a
// scenario set whose manifest is deep, mistyped, points outside the set or
// repeats ids; recordings that cannot be read; a player that never exits or
// prints without end; options that are not numbers; a commit a killed run
// left in the folder. Each run must end with the right exit code, keep the
// results it has and leave no staging, temporary folder or player behind.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>

using namespace railodd::test;
using ojson = nlohmann::ordered_json;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

// esmini: the scenario's first line says how to behave; its pid goes to
// player.pid beside the set. dat2csv: the recording says what to write.
const char* fake_esmini = R"SH(#!/bin/sh
osc=""; dat=""
while [ $# -gt 0 ]; do
  case "$1" in --osc) osc="$2"; shift;; --record) dat="$2"; shift;; esac; shift
done
echo "esmini GIT REV: fake"
mode=$(head -n 1 "$osc")
echo $$ > "$(dirname "$osc")/player.pid"
case "$mode" in
  SLEEP) exec sleep 100000;;
  SPAM) yes "a line the player prints again and again" | head -c 5000000;;
esac
echo "$mode" > "$dat"
)SH";

const char* fake_dat2csv = R"SH(#!/bin/sh
dat=""; csv=""
while [ $# -gt 0 ]; do
  case "$1" in --file) dat="$2"; shift;; --csv) csv="$2"; shift;; esac; shift
done
header="time, id, name, x, y, z, h, p, r, roadId, laneId, offset, t, s, speed"
case "$(cat "$dat")" in
  NOFILE) ;;
  EMPTY) : > "$csv";;
  NOH) echo "time, id, name, x, y, z, p, r, roadId, laneId, offset, t, s, speed" > "$csv";;
  SHORT) printf '%s\n0.0, 0, Ego, 1.0\n' "$header" > "$csv";;
  LANE) printf '%s\n0.0, 0, Ego, 0, 0, 0, 0, 0, 0, 1, 1e300, 0, 0, 0, 10\n' "$header" > "$csv";;
  *) printf '%s\n0.0, 0, Ego, 0, 0, 0, 0, 0, 0, 1, -1, 0, 0, 0, 10\n1.0, 0, Ego, 10, 0, 0, 0, 0, 0, 1, -1, 0, 0, 10, 10\n' "$header" > "$csv";;
esac
)SH";

fs::path install_player(const fs::path& dir, bool with_odrplot) {
    fs::create_directories(dir);
    write_file(dir / "esmini", fake_esmini);
    write_file(dir / "dat2csv", fake_dat2csv);
    std::vector<std::string> tools{"esmini", "dat2csv"};
    if (with_odrplot) {
        write_file(dir / "odrplot", "#!/bin/sh\necho 'lane, 1, 0, -1, driving' > \"$2\"\n");
        tools.push_back("odrplot");
    }
    for (const auto& t : tools) {
        fs::permissions(dir / t, fs::perms::owner_all, fs::perm_options::add);
    }
    return dir / "esmini";
}

ojson entry(const std::string& id) {
    return {{"id", id},
            {"template", "t"},
            {"file", id + ".xosc"},
            {"ego", {{"start", {{"road_id", "1"}, {"lane_id", -1}, {"s", 0.0}}}, {"route_roads", {"1"}},
                     {"length_m", 20.0}, {"width_m", 3.0}, {"max_deceleration", 0.7}, {"speed_kmh", 36.0},
                     {"run_up_m", 100.0}, {"overrun_m", 10.0}}},
            {"anchor", {{"road_id", "1"}, {"s", 50.0}}},
            {"actors", ojson::array()}};
}

// A set of scenarios, each id with the player's behaviour as its .xosc.
fs::path make_set(const fs::path& dir, const std::vector<std::pair<std::string, std::string>>& id_mode) {
    fs::create_directories(dir);
    ojson m = {{"scenarios", ojson::array()}};
    for (const auto& [id, mode] : id_mode) {
        m["scenarios"].push_back(entry(id));
        write_file(dir / (id + ".xosc"), mode + "\n");
    }
    write_file(dir / "manifest.json", m.dump(1));
    return dir;
}

ojson read_json(const fs::path& p) { return ojson::parse(read_file(p)); }

bool leftovers(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (n.rfind(".railodd-staging-", 0) == 0 || n == ".railodd-journal") {
            return true;
        }
    }
    return false;
}

std::string play(const fs::path& set, const fs::path& player, const std::string& more = "") {
    return "play " + quoted(set) + " --player " + quoted(player) + " --jobs 2 --quiet " + more;
}

} // namespace

TEST(CliHostilePlay, DeeplyNestedManifestIsRefusedNamingIt) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}});
    write_file(set / "manifest.json", std::string(1000000, '['));
    const auto r = run_railodd(play(set, player));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("manifest.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("nested deeper"), std::string::npos) << r.output;
    EXPECT_FALSE(leftovers(set));
    EXPECT_FALSE(fs::exists(set / "player.pid")); // refused before anything was played
}

TEST(CliHostilePlay, WronglyTypedManifestFieldsAreInputErrorsWithTheirPath) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const std::vector<std::pair<std::string, ojson>> cases = {
        {"/scenarios/0/file", 5}, {"/scenarios/0/actors", 5}, {"/scenarios/0/anchor/s", "12"},
        {"/scenarios/0/ego/route_roads/0", 7}};
    for (const auto& [pointer, value] : cases) {
        const fs::path set = make_set(dir / "set", {{"a", "OK"}});
        ojson m = read_json(set / "manifest.json");
        m[ojson::json_pointer(pointer)] = value;
        write_file(set / "manifest.json", m.dump());
        const auto r = run_railodd(play(set, player));
        EXPECT_EQ(r.exit_code, 2) << pointer << ": " << r.output;
        EXPECT_NE(r.output.find("manifest.json: " + pointer), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(set / "player.pid")) << pointer;
        fs::remove_all(set);
    }
}

TEST(CliHostilePlay, AnUnreadableRecordingFailsOnlyItsScenario) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const std::vector<std::pair<std::string, std::string>> runs = {
        {"good", "OK"}, {"empty", "EMPTY"}, {"none", "NOFILE"}, {"no_h", "NOH"}, {"short", "SHORT"}, {"lane", "LANE"}};
    const fs::path set = make_set(dir / "set", runs);
    const auto r = run_railodd(play(set, player));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    const ojson report = read_json(set / "play.json");
    ASSERT_EQ(report["scenarios"].size(), runs.size());
    EXPECT_TRUE(report["scenarios"][0].contains("criticality")) << report["scenarios"][0];
    for (std::size_t i = 1; i < runs.size(); ++i) {
        const ojson& s = report["scenarios"][i];
        EXPECT_FALSE(s["passed"].get<bool>()) << s;
        EXPECT_NE(s.value("error", "").find("play/" + runs[i].first + ".csv"), std::string::npos) << s;
    }
    EXPECT_NE(report["scenarios"][5]["error"].get<std::string>().find("lane id"), std::string::npos);
    EXPECT_FALSE(leftovers(set));
}

TEST(CliHostilePlay, NonFiniteOrNonPositiveNumbersAreRefused) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}});
    for (const std::string opt : {"--reaction-time nan", "--timestep nan", "--timestep 0", "--reaction-time inf",
                                  "--player-timeout nan", "--player-timeout 0"}) {
        const auto r = run_railodd(play(set, player, opt));
        EXPECT_EQ(r.exit_code, 1) << opt << ": " << r.output;
        EXPECT_NE(r.output.find(opt.substr(0, opt.find(' '))), std::string::npos) << r.output;
    }
    ojson m = read_json(set / "manifest.json");
    m["scenarios"][0]["ego"]["max_deceleration"] = 0;
    write_file(set / "manifest.json", m.dump());
    const auto r = run_railodd(play(set, player));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("/scenarios/0/ego/max_deceleration"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(set / "player.pid"));
}

TEST(CliHostilePlay, ScenarioFilesOutsideTheSetAreRefused) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    for (const std::string file : {"/etc/passwd", "../../x.xosc", "sub/../../x.xosc"}) {
        const fs::path set = make_set(dir / "set", {{"a", "OK"}});
        ojson m = read_json(set / "manifest.json");
        m["scenarios"][0]["file"] = file;
        write_file(set / "manifest.json", m.dump());
        const auto r = run_railodd(play(set, player));
        EXPECT_EQ(r.exit_code, 2) << file << ": " << r.output;
        EXPECT_NE(r.output.find("'" + file + "' is not a file inside the scenario folder"), std::string::npos)
            << r.output;
        EXPECT_FALSE(fs::exists(set / "player.pid")) << file;
        fs::remove_all(set);
    }
}

TEST(CliHostilePlay, DuplicateScenarioIdsAreRefused) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}, {"b", "OK"}});
    ojson m = read_json(set / "manifest.json");
    m["scenarios"][1]["id"] = "a";
    write_file(set / "manifest.json", m.dump());
    const auto r = run_railodd(play(set, player));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("scenario id 'a' is given twice"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(set / "player.pid"));
}

TEST(CliHostilePlay, PlotWithoutOdrplotIsRefusedBeforePlaying) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}});
    const auto r = run_railodd(play(set, player, "--plot"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("odrplot"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(set / "player.pid"));
}

TEST(CliHostilePlay, APlayerThatNeverExitsTimesOutAndTheOthersStand) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}, {"hang", "SLEEP"}});
    const auto r = run_railodd(play(set, player, "--player-timeout 1"));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    const ojson report = read_json(set / "play.json");
    EXPECT_TRUE(report["scenarios"][0].contains("criticality"));
    EXPECT_NE(report["scenarios"][1]["error"].get<std::string>().find("timed out"), std::string::npos)
        << report["scenarios"][1];
    const pid_t pid = std::stoi(read_file(set / "player.pid"));
    EXPECT_NE(::kill(pid, 0), 0) << "the player still runs"; // killed and reaped
}

TEST(CliHostilePlay, APlayerPrintingWithoutEndHasItsLogCapped) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"spam", "SPAM"}});
    run_railodd(play(set, player));
    const std::string log = read_file(set / "play" / "spam.log");
    EXPECT_LE(log.size(), (1u << 20) + 200u);
    EXPECT_EQ(log.rfind("esmini GIT REV: fake", 0), 0u); // the head is kept
    EXPECT_NE(log.find("bytes of this log left out"), std::string::npos);
}

// SIGTERM while the player runs: the player is killed, the staging and
// temporary folders removed; SIGKILL's leftovers go with the next run.
TEST(CliHostilePlay, SigtermKillsThePlayerAndLeavesNothing) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"hang", "SLEEP"}});
    const pid_t railodd = ::fork();
    if (railodd == 0) {
        ::execl(RAILODD_BIN, RAILODD_BIN, "play", set.c_str(), "--player", player.c_str(), "--quiet", nullptr);
        ::_exit(127);
    }
    for (int i = 0; i < 600 && !fs::exists(set / "player.pid"); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100)); // the pid written in full
    ASSERT_TRUE(fs::exists(set / "player.pid"));
    ::kill(railodd, SIGTERM);
    int status = 0;
    ::waitpid(railodd, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
    const pid_t pid = std::stoi(read_file(set / "player.pid"));
    EXPECT_NE(::kill(pid, 0), 0) << "the player still runs";
    EXPECT_FALSE(leftovers(set));
    const std::string mine = "railodd-play-" + std::to_string(railodd) + "-";
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path())) {
        EXPECT_NE(e.path().filename().string().rfind(mine, 0), 0u) << e.path();
    }
}

TEST(CliHostilePlay, TemporaryFoldersOfDeadRunsAreRemoved) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"a", "OK"}});
    const fs::path dead = fs::temp_directory_path() / "railodd-play-999999999-test";
    fs::create_directories(dead);
    run_railodd(play(set, player));
    EXPECT_FALSE(fs::exists(dead));
}

// A `scenarios` run killed in its commit left its journal: play finishes that
// commit before it reads the manifest, and so plays the new set.
TEST(CliHostilePlay, APendingCommitIsFinishedBeforeTheManifestIsRead) {
    const fs::path dir = scratch_dir(), player = install_player(dir / "bin", false);
    const fs::path set = make_set(dir / "set", {{"old", "OK"}});
    const fs::path staging = set / ".railodd-staging-999999999";
    make_set(staging, {{"new", "OK"}});
    write_file(set / ".railodd-journal", ".railodd-staging-999999999\n+ manifest.json\n+ new.xosc\n");
    run_railodd(play(set, player));
    const ojson report = read_json(set / "play.json");
    ASSERT_EQ(report["scenarios"].size(), 1u);
    EXPECT_EQ(report["scenarios"][0]["id"], "new");
    EXPECT_EQ(read_json(set / "manifest.json")["scenarios"][0]["id"], "new");
    EXPECT_FALSE(leftovers(set));
}
