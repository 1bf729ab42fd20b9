#include "store_merge.h"

#include "store_clips.h"

#include <deformseg/exceptions.h>
#include <deformseg/store/motion_store.h>
#include <deformseg/store/store_append.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <system_error>

namespace deformseg::frontend {

Describe_report merge_stores(const std::string& folder, const std::vector<std::string>& parts,
                             const std::function<void(const std::string&)>& say) {
  Describe_report report;
  if (parts.empty()) {
    std::error_code error;
    if (std::filesystem::exists(std::filesystem::path(folder) / "store.json", error))
      report.clips = store::Motion_store::open(folder).size();
    return report;
  }
  const store::Motion_store first = store::Motion_store::open(parts.front());
  store::Store_append append(folder, first.description(), first.summary_width(), first.summary_layout());
  for (const std::string& name : parts) {
    const store::Motion_store part = store::Motion_store::open(name);
    if (part.description() != first.description() || part.summary_layout() != first.summary_layout())
      throw invalid_input("this part's clips were described with other options than " + parts.front() + "'s",
                          {.file = name});
    say("merging " + std::to_string(part.size()) + " clip(s) of " + name);
    for (std::size_t i = 0; i < part.size(); ++i) {
      part.verify_clip(i);  // never carry a corrupted block into the merged store under a new checksum
      const store::Store_record record = part.record(i);
      const std::vector<std::uint32_t> frames(part.frames(i).begin(), part.frames(i).end());
      const std::string clip_name = stored_clip_name(part, i);
      if (const std::optional<std::size_t> at = append.find(record.path, record.clip, record.body)) {
        append.replace(*at, record, part.view(i), frames, part.summary(i));
        report.redescribed.push_back(clip_name);
      } else {
        append.add(record, part.view(i), frames, part.summary(i));
        report.described.push_back(clip_name);
      }
    }
  }
  append.commit();
  report.clips = append.size();
  return report;
}

}  // namespace deformseg::frontend
