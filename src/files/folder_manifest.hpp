// The record of what beachball wrote into an output folder: a hidden file listing the
// names of its files there. beachball replaces or removes a file of an output folder only
// when this record lists it; anything else in the folder is the user's.
#pragma once

#include <set>
#include <string>

namespace bb {

/// The record's file name inside an output folder.
inline constexpr const char* kManifestName = ".beachball-manifest";

/// The names the record of `folder` lists (empty when it has none).
std::set<std::string> read_manifest(const std::string& folder);

/// Whether `folder` has a record.
bool has_manifest(const std::string& folder);

/// The record's text for `names`.
std::string manifest_text(const std::set<std::string>& names);

/// Whether `folder` is a folder beachball wrote whole (a case's trajectories): a real folder
/// (not a link) with a record, holding nothing but the record and plain files it lists.
/// Otherwise, with `foreign`, the name of the first entry it does not list ("" when the
/// folder itself is not one).
bool holds_only_recorded_files(const std::string& folder, std::string* foreign = nullptr);

/// Whether `folder` holds a report written before beachball kept records: its README.md
/// starts with the report's heading and every other entry is a plain file of a kind a
/// report writes (.md, .json, .csv, .svg).
bool earlier_report(const std::string& folder);

}  // namespace bb
