// Digests of an HDF5 file's contents, so that a checkpoint changed or damaged after it was written
// is refused rather than continued (dem/output/checkpoint.hpp).
//
// The digest is of what the file holds, not of its bytes (HDF5 moves its own metadata when a group
// is added): every link's name, and every dataset's and attribute's type, shape and values, walked
// in name order. It is kept part by part, one SHA-256 (OpenSSL) per top-level group and one per group
// of /checkpoint, so that a refusal can say what differs: the scenario in /meta, a recorded row in
// /load, a record of /checkpoint/world.
//
// It guards against accidents (a flipped bit, an edit with h5py, a file of another run copied over),
// not against someone who means to forge a checkpoint: anyone can recompute it.
#pragma once

#include <H5Cpp.h>

#include <map>
#include <string>
#include <vector>

namespace icedem {

/// A part of the file ("/" for the root's own attributes, "/meta", "/load", "/checkpoint/world", ...)
/// and the hexadecimal SHA-256 of everything in it.
using FileDigest = std::map<std::string, std::string>;

/// The digest of `file`, leaving out the attribute `skip_attribute` of the group `skip_group`: where
/// the digest itself is kept.
FileDigest file_digest(const H5::H5File& file, const std::string& skip_group = "",
                       const std::string& skip_attribute = "");

/// One line per part, "part digest", as kept in the file; and back. parse_digest throws
/// std::invalid_argument on a line that is not one.
std::string format_digest(const FileDigest& digest);
FileDigest parse_digest(const std::string& text);

/// The parts in which `now` differs from `recorded`: changed, missing or added, in name order.
std::vector<std::string> digest_differences(const FileDigest& recorded, const FileDigest& now);

}  // namespace icedem
