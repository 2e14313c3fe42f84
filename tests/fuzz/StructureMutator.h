#pragma once
// Mutations that know a format's structure: they change what a reader trusts (a header's
// counts and sizes, a compression header's block count, a key's value, a field's type),
// where a byte flip would mostly hit data or break a checksum. One per format:
//  - text headers (NRRD, MetaImage, .seg.nrrd, PLY, .msh, OBJ, CSV, YAML, JSON state):
//    a key's value replaced by a hostile one (counts of 2^32 and 2^64, negative, NaN,
//    a 30,000-character value, /dev/zero or a pattern as a data file, deep nesting,
//    another JSON type);
//  - NIfTI: header fields at their offsets (dims, datatype, bitpix, voxel size,
//    vox_offset, scaling, sform);
//  - DICOM: the values of Rows, Columns, BitsAllocated, NumberOfFrames and element lengths;
//  - VTK XML: the binary header words of an appended array (block count, block size,
//    compressed sizes) and its NumberOf... attributes;
//  - STL: the triangle count;
//  - checkpoints: a field's name length, type or count, with the checksum made right again
//    so that the reader must judge the structure itself.
// Deterministic in (seed, case), like Mutator.h.
#include <cstdint>
#include <string>

namespace vesica::fuzz {

// `original` of reader `reader` ("nifti", "vtp", ...) mutated in its structure; the byte
// mutations of Mutator.h for a format without one, or when nothing structured is found.
std::string mutate_structure(const std::string& reader, const std::string& original,
                             std::uint64_t seed, std::uint64_t case_index);

}  // namespace vesica::fuzz
