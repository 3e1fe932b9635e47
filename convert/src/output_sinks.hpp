#pragma once
// convert's outputs as sinks of the ODD profile (odd::ProfileSink): each is
// fed the profile's head, its elements a batch at a time in profile order,
// and its tail, and stages its files (docs/ARCHITECTURE.md, "Outputs"). One
// class per output: a new format is one more. The memory policy of outputs:
// none holds the profile; each prints a batch and drops it (the profile's
// files) or keeps only what it writes at the end (the page's section, the
// map's user data). An output that reads only the map writes it on a thread
// of its own from begin() (`launch`: beside, or deferred with --threads 1)
// and waits for it in end().
#include "outputs.hpp"
#include "sink_thread.hpp"

#include "railodd/odd/profile_files.hpp"
#include "railodd/odd/tagger.hpp"
#include "railodd/xodr/xml_writer.hpp"

#include <future>
#include <memory>
#include <optional>
#include <vector>

namespace railodd::convert {

// Several outputs fed as one, in the order given. An output may take a
// batch's elements (ProfileSink): only the last may, so the profile's files
// come last.
class Outputs final : public odd::ProfileSink {
public:
    void push_back(std::unique_ptr<odd::ProfileSink> output) { outputs_.push_back(std::move(output)); }
    void begin(const odd::OddProfile& head) override;
    void add(std::deque<odd::TaggedElement>& batch) override;
    void end(const odd::OddProfile& tail) override;

private:
    std::vector<std::unique_ptr<odd::ProfileSink>> outputs_;
};

// odd_profile.json, .geojson and .csv (odd::ProfileFiles), written on a thread
// of their own (SinkThread) unless --threads 1. Takes the batches.
class ProfileFilesOutput final : public odd::ProfileSink {
public:
    ProfileFilesOutput(OutputStage& stage, bool own_thread);
    void begin(const odd::OddProfile& head) override { sink().begin(head); }
    void add(std::deque<odd::TaggedElement>& batch) override { sink().add(batch); }
    void end(const odd::OddProfile& tail) override;

private:
    odd::ProfileSink& sink() { return thread_ ? static_cast<odd::ProfileSink&>(*thread_) : files_; }
    StagedFile json_, geojson_, csv_;
    odd::ProfileFiles files_;
    std::optional<SinkThread> thread_; // after files_: stopped before they go
};

// map.xodr; with --odd-user-data, each road's elements as its <userData>,
// collected as the profile is fed and written at end().
class MapOutput final : public odd::ProfileSink {
public:
    MapOutput(OutputStage& stage, const xodr::Map& map, xodr::Revision revision, bool odd_user_data, std::launch launch);
    void begin(const odd::OddProfile& head) override;
    void add(std::deque<odd::TaggedElement>& batch) override;
    void end(const odd::OddProfile& tail) override;

private:
    void write(const xodr::ExtraUserData& user_data);
    OutputStage& stage_;
    const xodr::Map& map_;
    xodr::Revision revision_;
    std::optional<odd::OddUserData> user_data_;
    std::launch launch_;
    std::future<void> written_;
};

// ingest.geojson, geometry.geojson and roads.geojson with --debug-outputs:
// the selected input and the fitted track and road centrelines in WGS84.
// Without it, any left by an earlier run go: they would describe another map.
class DebugOutput final : public odd::ProfileSink {
public:
    DebugOutput(OutputStage& stage, bool wanted, const ingest::IngestResult& result, const geometry::FittedMap& geo,
                std::launch launch);
    void begin(const odd::OddProfile& head) override;
    void add(std::deque<odd::TaggedElement>&) override {}
    void end(const odd::OddProfile& tail) override;

private:
    OutputStage& stage_;
    bool wanted_;
    const ingest::IngestResult& result_;
    const geometry::FittedMap& geo_;
    std::launch launch_;
    std::future<void> written_;
};

// What report.json and report.html keep of the profile (Profiled): its tail,
// and (page_map given) the page's section, fed element by element.
class PageSectionOutput final : public odd::ProfileSink {
public:
    PageSectionOutput(Profiled& out, const xodr::Map* page_map) : out_(out), page_map_(page_map) {}
    void begin(const odd::OddProfile& head) override;
    void add(std::deque<odd::TaggedElement>& batch) override;
    void end(const odd::OddProfile& tail) override { out_.profile = tail; }

private:
    Profiled& out_;
    const xodr::Map* page_map_;
};

} // namespace railodd::convert
