#include "vesica/pipelines/Staleness.h"

#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "vesica/core/ContentHash.h"
#include "vesica/core/StageRecord.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

bool is_option(const std::string& token) {
  return token.size() > 1 && token[0] == '-';
}

// Options of an invocation: --key -> value ("" for a bare flag), plus the positionals.
struct ParsedInvocation {
  std::map<std::string, std::string> options;
  std::vector<std::string> positional;
};

ParsedInvocation parse(const std::vector<std::string>& argv) {
  ParsedInvocation p;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (!is_option(argv[i])) {
      p.positional.push_back(argv[i]);
    } else if (i + 1 < argv.size() && !is_option(argv[i + 1])) {
      p.options[argv[i]] = argv[i + 1];
      ++i;
    } else {
      p.options[argv[i]] = "";
    }
  }
  return p;
}

std::string pipeline_key(const std::string& option) {
  std::string key = option.substr(option.find_first_not_of('-'));
  for (char& c : key)
    if (c == '-') c = '_';
  return key;
}

std::string shown(const std::string& value) {
  return value.empty() ? "on" : value;
}

// vesica_core 0.1 sums folder stamps with max(0, mtime) while libstdc++'s file_clock
// counts from an epoch after today, so a folder's recorded mtime is just a small count and
// cannot tell an edit that keeps the folder's size. A real mtime in ns is far larger.
bool stamp_is_trustworthy(const FileRecord& r) {
  return r.mtime_ns > 1'000'000'000'000LL || r.mtime_ns < -1'000'000'000'000LL;
}

// For such folders: nothing inside (files, subfolders, the folder itself) was modified
// after the manifest was written, which happens after the stage wrote its outputs.
bool folder_untouched_since(const fs::path& dir, fs::file_time_type manifest_time) {
  std::error_code ec;
  if (fs::last_write_time(dir, ec) > manifest_time || ec) return false;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.last_write_time(ec) > manifest_time || ec) return false;
  return !ec;
}

// Checks a recorded file against the disk: "" when unchanged, else what happened.
// The recorded hash is trusted while size and mtime are unchanged (for folders with an
// unusable recorded mtime: while nothing inside is newer than the manifest).
std::string compare_file(const fs::path& path, const FileRecord& recorded,
                         fs::file_time_type manifest_time) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return "missing";
  FileStamp now;
  try {
    now = file_stamp(path);
  } catch (const std::exception&) {
    return "unreadable";
  }
  if (now.size == recorded.size) {
    if (stamp_is_trustworthy(recorded) && now.mtime_ns == recorded.mtime_ns) return "";
    if (!stamp_is_trustworthy(recorded) && fs::is_directory(path, ec) &&
        folder_untouched_since(path, manifest_time))
      return "";
  }
  try {
    return content_hash(path) == recorded.hash ? "" : "changed";
  } catch (const std::exception&) {
    return "unreadable";
  }
}

std::vector<std::string> strings(const nlohmann::json& j) {
  std::vector<std::string> out;
  if (j.is_array())
    for (const auto& x : j)
      if (x.is_string()) out.push_back(x.get<std::string>());
  return out;
}

}  // namespace

const char* to_string(Freshness f) {
  switch (f) {
    case Freshness::Fresh:
      return "fresh";
    case Freshness::Stale:
      return "stale";
    case Freshness::Missing:
      return "missing";
  }
  return "stale";
}

std::string describe_invocation_change(const std::vector<std::string>& before,
                                       const std::vector<std::string>& after) {
  const ParsedInvocation a = parse(before), b = parse(after);
  for (const auto& [option, value] : b.options) {
    auto it = a.options.find(option);
    if (it == a.options.end())
      return "parameter " + pipeline_key(option) + " added (" + shown(value) + ")";
    if (it->second != value)
      return "parameter " + pipeline_key(option) + " changed (" + shown(it->second) + " -> " +
             shown(value) + ")";
  }
  for (const auto& [option, value] : a.options)
    if (!b.options.count(option)) return "parameter " + pipeline_key(option) + " removed";
  if (a.positional != b.positional) return "inputs on the command line changed";
  return "command line changed (argument order)";
}

StageStatus assess_stage(const Plan& plan, std::size_t index) {
  const PlannedStage& s = plan.stages[index];
  const fs::path manifest_path = plan.in_workdir(s.manifest);
  std::ifstream in(manifest_path);
  if (!in) return {Freshness::Missing, "not run yet (no manifest " + s.manifest + ")"};
  nlohmann::json m = nlohmann::json::parse(in, nullptr, false);
  if (m.is_discarded() || !m.is_object())
    return {Freshness::Stale, "manifest " + s.manifest + " is unreadable"};
  std::error_code ec;
  const fs::file_time_type manifest_time = fs::last_write_time(manifest_path, ec);
  const std::string recorded_version = m.value("version", "");
  if (recorded_version != vesica::version())
    return {Freshness::Stale,
            "tool version changed (" + recorded_version + " -> " + vesica::version() + ")"};
  const std::vector<std::string> invocation = strings(m.value("invocation", nlohmann::json()));
  if (invocation != s.argv)
    return {Freshness::Stale, describe_invocation_change(invocation, s.argv)};
  for (const auto& j : m.value("inputs", nlohmann::json::array())) {
    const FileRecord r = file_record_from_json(j);
    const std::string what = compare_file(plan.in_workdir(r.path), r, manifest_time);
    if (what.empty()) continue;
    std::string reason = "input " + r.path + " " + what;
    const long producer = plan.producer_of(r.path);
    if (producer >= 0) reason += " (upstream " + plan.stages[producer].id + ")";
    return {Freshness::Stale, reason};
  }
  for (const auto& j : m.value("outputs", nlohmann::json::array())) {
    const FileRecord r = file_record_from_json(j);
    const std::string what = compare_file(plan.in_workdir(r.path), r, manifest_time);
    if (what == "missing") return {Freshness::Stale, "output " + r.path + " is missing"};
    if (!what.empty()) return {Freshness::Stale, "output " + r.path + " was edited"};
  }
  return {Freshness::Fresh, ""};
}

std::vector<StageStatus> assess(const Plan& plan) {
  std::vector<StageStatus> out;
  for (std::size_t i = 0; i < plan.stages.size(); ++i) {
    StageStatus st = assess_stage(plan, i);
    if (st.state == Freshness::Fresh)
      for (std::size_t d : plan.stages[i].deps)
        if (out[d].state != Freshness::Fresh) {
          st = {Freshness::Stale,
                "upstream " + plan.stages[d].id + " is " + to_string(out[d].state)};
          break;
        }
    out.push_back(st);
  }
  return out;
}

}  // namespace vesica::pipelines
