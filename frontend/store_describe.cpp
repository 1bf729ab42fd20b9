#include "store_describe.h"

#include "clip_cache.h"
#include "outputs.h"
#include "store_describe_clip.h"
#include "store_policy.h"
#include "store_staleness.h"

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/character_files.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/store/store_append.h>
#include <deformseg/store/stored_motions.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <system_error>
#include <utility>

namespace deformseg::frontend {

namespace {

// The clips described at once, then appended in order: at least 32, so that few threads wait for
// the batch's last clip; 4 per thread on more than 8. At most `threads` clips are read at once.
std::size_t describe_batch(int threads) { return std::max<std::size_t>(32, 4 * std::size_t(threads)); }

// The clips of `clips` to describe, their records in `records`: those the store lacks or holds
// changed, a file's together in the order of the files' first clips (the order they are appended
// in); the others are reported skipped.
std::vector<std::size_t> clips_to_describe(const std::vector<Clip_source>& clips, const Input_options& options,
                                           bool hash, bool skip_unreadable, const store::Motion_store& store,
                                           std::vector<store::Store_record>& records, Describe_report& report) {
  std::map<std::string, std::vector<std::size_t>> of_file;
  std::vector<std::string> files;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    try {
      records[i] = source_record(clips[i], options, hash);
    } catch (const invalid_input& e) {
      if (!skip_unreadable) throw;
      report.unreadable.push_back(clips[i].name() + ": " + utf8_text(e.what()));
      continue;
    }
    const std::optional<std::size_t> at = find_clip(store, clips[i]);
    if (at && unchanged(store.record(*at), records[i], hash)) {
      report.skipped.push_back(clips[i].name());
      continue;
    }
    if (!of_file.count(clips[i].file)) files.push_back(clips[i].file);
    of_file[clips[i].file].push_back(i);
  }
  std::vector<std::size_t> order;
  for (const std::string& file : files) order.insert(order.end(), of_file[file].begin(), of_file[file].end());
  return order;
}

// "45 s", "3 min 20 s", "2 h 5 min": a duration as a progress line gives it.
std::string duration_text(double seconds) {
  const auto whole = std::uint64_t(std::max(0.0, std::round(seconds)));
  if (whole < 60) return std::to_string(whole) + " s";
  if (whole < 3600) return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
  return std::to_string(whole / 3600) + " h " + std::to_string(whole / 60 % 60) + " min";
}

// A line per clip described, with the rates so far and the time left at that rate: said under a
// lock by the thread that described the clip, so that a long batch still shows its progress.
class Clip_progress {
public:
  Clip_progress(std::size_t total, const std::function<void(const std::string&)>& say) : total_(total), say_(say) {}

  void described(const Clip_source& clip, std::size_t frames) {
    const std::lock_guard lock(mutex_);
    ++done_, frames_ += frames;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char rates[64];
    std::snprintf(rates, sizeof rates, "%.1f clips/s, %.0f frames/s", double(done_) / seconds,
                  double(frames_) / seconds);
    say_("described " + std::to_string(done_) + " of " + std::to_string(total_) + ": " + clip.name() + " (" +
         std::to_string(frames) + " frames); " + rates + ", about " +
         duration_text(seconds / double(done_) * double(total_ - done_)) + " left");
  }

private:
  std::mutex mutex_;
  std::size_t total_, done_ = 0, frames_ = 0;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  const std::function<void(const std::string&)>& say_;
};

// Says "describing N clip(s) of FILE" for each file whose first clip is among order[first, end).
void announce_files(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& order, std::size_t first,
                    std::size_t end, const std::function<void(const std::string&)>& say) {
  for (std::size_t k = first; k < end; ++k) {
    const std::string& file = clips[order[k]].file;
    if (k > 0 && clips[order[k - 1]].file == file) continue;
    std::size_t count = 1;
    while (k + count < order.size() && clips[order[k + count]].file == file) ++count;
    say("describing " + std::to_string(count) + " clip(s) of " + file);
  }
}

// The store a run appends to, committed when asked and at the end: a commit ends an append, the
// next clip starts another.
class Store_writer {
public:
  Store_writer(const std::string& folder, const similarity::Default_similarity& policy)
      : folder_(folder), policy_(policy), append_(start()) {}

  const store::Motion_store& store() const { return append_->store(); }

  // Appends `described` as clip `clip` of `record` (replacing the clip's old description, if any).
  void append(const Clip_source& clip, const store::Store_record& record, const Described_clip& described,
              Describe_report& report) {
    if (!append_) append_ = start();
    const signatures::Motion_signature_view view = similarity::view(described.description);
    const std::vector<std::uint32_t> frames(described.description.frames.begin(), described.description.frames.end());
    if (const std::optional<std::size_t> at = append_->store().find(record.path, record.clip, record.body)) {
      append_->replace(*at, record, view, frames, described.summary.floats);
      report.redescribed.push_back(clip.name());
    } else {
      append_->add(record, view, frames, described.summary.floats);
      report.described.push_back(clip.name());
    }
    ++appended_;
  }

  // Commits the clips appended since the last commit, if any.
  void commit_appended(Describe_report& report) {
    if (append_ && appended_ > 0) commit(report);
  }

  // Commits what the run left uncommitted: at least the store's making, when nothing was appended.
  void finish(Describe_report& report) {
    if (append_) commit(report);
  }

private:
  std::unique_ptr<store::Store_append> start() const {
    return std::make_unique<store::Store_append>(folder_, store_description(policy_),
                                                 search::summary_width(signature_width(policy_), store_summary_chunks),
                                                 store::motion_summary_layout(store_summary_chunks));
  }

  void commit(Describe_report& report) {
    report.clips = append_->size();
    append_->commit();
    append_.reset();
    appended_ = 0;
  }

  const std::string& folder_;
  const similarity::Default_similarity& policy_;
  std::unique_ptr<store::Store_append> append_;
  std::size_t appended_ = 0;  // since the last commit
};

// The clips of a batch described, or why not, by their place in the batch.
struct Described_batch {
  std::vector<Described_clip> described;
  std::vector<std::optional<invalid_input>> errors;
};

// The character files of the clips `order` names, a clip each.
std::vector<Character_on_body> files_of(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& order) {
  std::vector<Character_on_body> files;
  for (const std::size_t i : order) files.push_back({clips[i].file, clips[i].body});
  return files;
}

// One run of `describe_into_store` over the clips `order` names, a batch at a time.
class Description_run {
public:
  Description_run(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& order,
                  const Input_options& options, const similarity::Default_similarity& policy, const Describe_run& run,
                  const std::function<void(const std::string&)>& say)
      : clips_(clips), order_(order), options_(options), policy_(policy), run_(run), say_(say),
        cache_(files_of(clips, order), options), progress_(order.size(), say) {
    // A batch of one clip leaves the threads to its rows: they take the clips' threads.
    policy_.signatures.threads = options.threads;
  }

  Clip_cache& cache() { return cache_; }

  // Describes the clips of `order` into `writer`, their records in `records`, as `describe_into_store` says.
  void describe(Store_writer& writer, std::vector<store::Store_record>& records, Describe_report& report) {
    const std::size_t batch = describe_batch(thread_count(options_.threads));
    for (std::size_t first = 0; first < order_.size(); first += batch) {
      const std::size_t count = std::min(batch, order_.size() - first);
      announce_files(clips_, order_, first, first + count, say_);
      store_batch(describe_batch_of(first, count), first, writer, records, report);
    }
  }

private:
  // Clip `clip` described, its character file (if it is one) taken from the cache.
  Described_clip describe_one(const Clip_source& clip) {
    if (!io::is_character_file(clip.file)) return describe_clip(clip, nullptr, nullptr, options_, policy_, run_.front);
    const Character_on_body file{clip.file, clip.body};
    const Clip_cache::Release release(cache_, file);
    const std::shared_ptr<const io::Gltf_file> gltf = cache_.acquire(file);
    return describe_clip(clip, gltf.get(), cache_.connectivity(file), options_, policy_, run_.front);
  }

  // The clips order[first, first + count) described, a clip per thread, by the library's one
  // parallel loop (a detail: threads.h has no public loop): a batch of one clip leaves the threads
  // to its rows (loops nested in a loop of several threads run on one). A clip that cannot be read
  // or described is noted, not thrown, so that the clips before it are stored whatever the threads did.
  Described_batch describe_batch_of(std::size_t first, std::size_t count) {
    Described_batch batch{std::vector<Described_clip>(count), std::vector<std::optional<invalid_input>>(count)};
    deformseg::internal::parallel_for(count, options_.threads, [&](std::size_t k) {
      const Clip_source& clip = clips_[order_[first + k]];
      try {
        batch.described[k] = describe_one(clip);
        progress_.described(clip, batch.described[k].frame_count);
      } catch (const invalid_input& e) {
        batch.errors[k] = e;
      }
    });
    return batch;
  }

  // Appends the batch from order[first] in order, committing every `store_commit_clips` of the run.
  // @throws invalid_input for a clip that failed, without `skip_unreadable`, after a commit.
  void store_batch(const Described_batch& batch, std::size_t first, Store_writer& writer,
                   std::vector<store::Store_record>& records, Describe_report& report) {
    for (std::size_t k = 0; k < batch.described.size(); ++k) {
      const Clip_source& clip = clips_[order_[first + k]];
      if (batch.errors[k]) {
        left_out(clip, *batch.errors[k], writer, report);
      } else {
        if (!batch.described[k].warning.empty()) say_("warning: " + clip.name() + ": " + batch.described[k].warning);
        store::Store_record& record = records[order_[first + k]];
        record.frame_count = batch.described[k].frame_count;
        record.fps = batch.described[k].fps;
        writer.append(clip, record, batch.described[k], report);
      }
      if ((first + k + 1) % store_commit_clips == 0) writer.commit_appended(report);
    }
  }

  // A clip that could not be read or described: reported with `skip_unreadable`, else thrown
  // after the clips before it are committed.
  void left_out(const Clip_source& clip, const invalid_input& error, Store_writer& writer, Describe_report& report) {
    if (!run_.skip_unreadable) {
      writer.commit_appended(report);
      throw invalid_input(error.message() + " (" + spelled("skip_unreadable", run_.front) + " leaves it out; the " +
                              std::to_string(report.described.size() + report.redescribed.size()) +
                              " clip(s) described before it are in the store)",
                          error.where());
    }
    say_("left out " + clip.name() + ": " + error.what());
    report.unreadable.push_back(clip.name() + ": " + utf8_text(error.what()));
  }

  const std::vector<Clip_source>& clips_;
  const std::vector<std::size_t>& order_;
  const Input_options& options_;
  similarity::Default_similarity policy_;  // on the clips' threads
  const Describe_run& run_;
  const std::function<void(const std::string&)>& say_;
  Clip_cache cache_;
  Clip_progress progress_;
};

// `describe_into_store`, taking the files that `listed` holds parsed.
Describe_report describe_clips(const std::string& folder, const std::vector<Clip_source>& clips,
                               const Input_options& options, const similarity::Default_similarity& policy,
                               const Describe_run& run, const std::function<void(const std::string&)>& say,
                               Listed_parses* listed) {
  Store_writer writer(folder, policy);
  Describe_report report;
  std::vector<store::Store_record> records(clips.size());
  const std::vector<std::size_t> order =
      clips_to_describe(clips, options, run.hash, run.skip_unreadable, writer.store(), records, report);
  Description_run described(clips, order, options, policy, run, say);
  if (listed) described.cache().adopt(*listed);
  described.describe(writer, records, report);
  writer.finish(report);
  return report;
}

}  // namespace

Describe_report describe_into_store(const std::string& folder, const std::vector<Clip_source>& clips,
                                    const Input_options& options, const similarity::Default_similarity& policy,
                                    const Describe_run& run, const std::function<void(const std::string&)>& say) {
  return describe_clips(folder, clips, options, policy, run, say, nullptr);
}

Describe_report describe_inputs(const std::string& folder, const std::vector<std::string>& inputs,
                                const Input_options& options, const similarity::Default_similarity& policy,
                                const Describe_run& run, const std::function<void(const std::string&)>& say) {
  std::vector<std::string> poses, unlisted;
  Listed_parses listed;
  const std::vector<Clip_source> clips =
      clip_sources(inputs, options, poses, run.skip_unreadable ? &unlisted : nullptr, &listed);
  say(std::to_string(clips.size()) + " clip(s) named by the inputs");
  for (const std::string& pose : poses) say("left out " + pose + ": a pose of 1 frame, no motion");
  for (const std::string& input : unlisted) say("left out " + input);
  Describe_report report = describe_clips(folder, clips, options, policy, run, say, &listed);
  report.unreadable.insert(report.unreadable.begin(), unlisted.begin(), unlisted.end());
  report.poses = std::move(poses);
  return report;
}

Description_plan plan_description(const std::string& folder, const std::vector<Clip_source>& clips,
                                  const Input_options& options, const similarity::Default_similarity& policy,
                                  bool hash) {
  std::error_code error;
  const bool exists = std::filesystem::exists(std::filesystem::path(folder) / "store.json", error);
  const store::Motion_store store = exists ? store::Motion_store::open(folder) : store::Motion_store{};
  if (exists && nlohmann::json::parse(store.description()) != nlohmann::json::parse(store_description(policy)))
    throw invalid_input("the store's clips were described with other options (deformseg store info " + folder +
                            " gives them) than " + store_description(policy),
                        {.file = folder});
  Description_plan plan;
  std::vector<store::Store_record> records(clips.size());
  plan.order = clips_to_describe(clips, options, hash, false, store, records, plan.report);
  plan.report.clips = store.size();
  return plan;
}

}  // namespace deformseg::frontend
