// Inputs a hostile but fair tester made (issue 20) and bad MR inputs (issue 23): each is
// refused with one line naming the file and the problem, never a crash, never a silently
// wrong result; and no UID reaches an output or a message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include <gdcmReader.h>
#include <gdcmSequenceOfItems.h>
#include <gdcmWriter.h>
#include <itkImageFileWriter.h>

#include "SegmentTestHelpers.h"
#include "vesica/segment/DicomSeries.h"

namespace fs = std::filesystem;
namespace seg = vesica::segment;
using vesica::test::expect_rejected;
using vesica::test::read_text;
using vesica::test::run_tool;
using vesica::test::small_series;

namespace {

const std::string kSeed = " --seed 0,-15,-10";  // the phantom bladder's centre

// Sets a text attribute of a DICOM file in place (gdcm), as a broken exporter would.
void set_attribute(const fs::path& file, std::uint16_t group, std::uint16_t element,
                   const gdcm::VR& vr, std::string value) {
  gdcm::Reader reader;
  reader.SetFileName(file.c_str());
  ASSERT_TRUE(reader.Read()) << file;
  if (value.size() % 2) value += ' ';
  gdcm::DataElement de(gdcm::Tag(group, element));
  de.SetVR(vr);
  de.SetByteValue(value.data(), static_cast<std::uint32_t>(value.size()));
  reader.GetFile().GetDataSet().Replace(de);
  gdcm::Writer writer;
  writer.SetFileName(file.c_str());
  writer.SetFile(reader.GetFile());
  ASSERT_TRUE(writer.Write()) << file;
}

// Adds a sequence of one item, both of undefined length, as scanners write them
// (ReferencedImageSequence holding one ReferencedSOPInstanceUID).
void add_referenced_image(const fs::path& file) {
  gdcm::Reader reader;
  reader.SetFileName(file.c_str());
  ASSERT_TRUE(reader.Read()) << file;
  gdcm::DataElement uid(gdcm::Tag(0x0008, 0x1155));
  uid.SetVR(gdcm::VR::UI);
  uid.SetByteValue("1.2.3.4", 8);  // with its padding NUL
  gdcm::Item item;
  item.SetVLToUndefined();
  item.GetNestedDataSet().Insert(uid);
  gdcm::SmartPointer<gdcm::SequenceOfItems> sequence = new gdcm::SequenceOfItems;
  sequence->SetLengthToUndefined();
  sequence->AddItem(item);
  gdcm::DataElement de(gdcm::Tag(0x0008, 0x1140));
  de.SetVR(gdcm::VR::SQ);
  de.SetValue(*sequence);
  de.SetVLToUndefined();
  reader.GetFile().GetDataSet().Insert(de);
  gdcm::Writer writer;
  writer.SetFileName(file.c_str());
  writer.SetFile(reader.GetFile());
  ASSERT_TRUE(writer.Write()) << file;
}

// Where `bytes` first occur in the file after the 128-byte preamble and "DICM".
std::streamoff offset_of(const fs::path& file, const std::string& bytes) {
  const std::string text = read_text(file);
  const auto at = text.find(bytes, 132);
  EXPECT_NE(at, std::string::npos) << file;
  return static_cast<std::streamoff>(at);
}

std::vector<fs::path> slices_of(const fs::path& series) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(series)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// A small CT phantom as a float NIfTI (uncompressed, so header bytes can be patched).
fs::path nifti_phantom(const fs::path& dir, const std::string& name) {
  seg::PhantomSpec spec;
  spec.spacing_mm = 4.0;
  spec.fov_mm = {200, 200, 160};
  auto writer = itk::ImageFileWriter<seg::ScanImage>::New();
  writer->SetInput(seg::make_phantom(spec));
  writer->SetFileName((dir / name).string());
  writer->Update();
  return dir / name;
}

template <class T>
void patch(const fs::path& file, std::streamoff offset, T value) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(offset);
  f.write(reinterpret_cast<const char*>(&value), sizeof value);
}

// NIfTI-1 header offsets (bytes), as the standard's nifti1.h lays them out.
constexpr std::streamoff kPixdim = 76, kQformCode = 252, kSformCode = 254, kSrowX = 280;

}  // namespace

// GDCM asserts (SIGABRT) on a meta header cut short; every cut, early ones included,
// must come back as one line naming the slice.
TEST(HostileDicom, SliceCutShortAnywhereNamesTheSlice) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-cut");
  const auto good = small_series(dir, "ct");
  const auto full = fs::file_size(good / "slice_0010.dcm");
  for (const std::uintmax_t size :
       {std::uintmax_t{0}, std::uintmax_t{100}, std::uintmax_t{132}, std::uintmax_t{147},
        std::uintmax_t{161}, std::uintmax_t{196}, std::uintmax_t{266}, std::uintmax_t{300},
        std::uintmax_t{385}, std::uintmax_t{400}, std::uintmax_t{436}, std::uintmax_t{560},
        full / 2, full - 1}) {
    fs::remove_all(dir / "cut");
    fs::copy(good, dir / "cut");
    fs::resize_file(dir / "cut" / "slice_0010.dcm", size);
    SCOPED_TRACE("cut to " + std::to_string(size) + " bytes");
    expect_rejected(dir, (dir / "cut").string() + kSeed, "slice_0010.dcm");
  }
}

// A phantom series in scratch folder `name` whose slice `victim` is damaged by
// damage(dir, series, slice): vesica-segment refuses it with `message` in one line.
template <class Damage>
void expect_damaged_slice_refused(const std::string& name, const std::string& victim,
                                  const Damage& damage, const std::string& message) {
  const auto dir = vesica::test::scratch_dir(name);
  const auto series = small_series(dir, "ct");
  damage(dir, series, series / victim);
  expect_rejected(dir, series.string() + kSeed,
                  victim + ": truncated or corrupt DICOM file (" + message + ")");
}

// A length field that lies (here Rows, implicit VR little endian as the phantom series is
// written): GDCM allocated the 2.8 GB it names before noticing the file is shorter.
TEST(HostileDicom, ElementLongerThanTheFileIsRefusedBeforeGdcmAllocatesIt) {
  expect_damaged_slice_refused(
      "segment-hostile-length", "slice_0005.dcm",
      [](const fs::path&, const fs::path&, const fs::path& slice) {
        const std::string rows("\x28\x00\x10\x00", 4);
        patch(slice, offset_of(slice, rows) + 4, std::uint32_t{0xA980673C});
      },
      "element (0028,0010) of 2843764540 bytes runs past the end of its file");
}

// A meta element whose value representation is no VR of the standard: GDCM read the meta
// group as implicit VR and aborted on its own assertion ("Should not happen").
TEST(HostileDicom, MetaHeaderWithAnUnknownValueRepresentationIsRefused) {
  expect_damaged_slice_refused(
      "segment-hostile-meta-vr", "slice_0002.dcm",
      [](const fs::path&, const fs::path&, const fs::path& slice) {
        ASSERT_EQ(offset_of(slice, std::string("\x02\x00\x00\x00UL", 6)), 132);
        patch(slice, 136, 'Q');  // (0002,0000) UL becomes "QL", as a fuzzed file had it
      },
      "file meta information is not explicit VR");
}

// Sequences and items are walked: one of undefined length reads, and an item whose length
// runs past its file is refused before GDCM trusts it.
TEST(HostileDicom, SequenceItemLongerThanTheFileIsRefused) {
  expect_damaged_slice_refused(
      "segment-hostile-item", "slice_0003.dcm",
      [](const fs::path& dir, const fs::path& series, const fs::path& slice) {
        for (const auto& f : slices_of(series)) add_referenced_image(f);
        ASSERT_EQ(
            run_tool("vesica-segment",
                     series.string() + kSeed + " -o " + (dir / "nested.nii.gz").string(), dir),
            0)
            << read_text(dir / "stderr.txt");
        const std::string item_of_undefined_length("\xFE\xFF\x00\xE0\xFF\xFF\xFF\xFF", 8);
        patch(slice, offset_of(slice, item_of_undefined_length) + 4, std::uint32_t{0x7FFFFFF0});
      },
      "element (FFFE,E000) of 2147483632 bytes runs past the end of its file");
}

// Without the check the first or last slice was dropped and the series read 28 of 30.
TEST(HostileDicom, UnreadableFirstOrLastSliceIsNamedNotDropped) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-ends");
  const auto good = small_series(dir, "ct");
  const auto files = slices_of(good);
  for (const auto& victim : {files.front().filename(), files.back().filename()}) {
    fs::remove_all(dir / "bad");
    fs::copy(good, dir / "bad");
    std::ofstream(dir / "bad" / victim, std::ios::trunc) << "not an image any more";
    expect_rejected(dir, (dir / "bad").string() + kSeed, victim.string());
  }
}

TEST(HostileDicom, NonFinitePositionsAreRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-nan-position");
  const auto series = small_series(dir, "ct");
  for (const auto& f : slices_of(series))
    set_attribute(f, 0x0020, 0x0032, gdcm::VR::DS, "nan\\nan\\nan");
  expect_rejected(dir, series.string() + kSeed, "ImagePositionPatient");
}

TEST(HostileDicom, OneSliceWithAnotherPixelSpacingIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-spacing");
  const auto series = small_series(dir, "ct");
  set_attribute(series / "slice_0007.dcm", 0x0028, 0x0030, gdcm::VR::DS, "2.5\\2.5");
  expect_rejected(dir, series.string() + kSeed, "PixelSpacing differs");
}

// A dual-echo acquisition stored as one series: its echoes share positions. It is named
// for what it is, not for duplicate slices.
TEST(HostileDicom, MrSeriesOfMixedEchoTimesIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-echoes");
  const auto series = small_series(dir, "mr", 1, seg::Modality::MR);
  for (const auto& f : slices_of(series)) {
    const auto second = f.parent_path() / ("echo2_" + f.filename().string());
    fs::copy_file(f, second);
    set_attribute(second, 0x0018, 0x0081, gdcm::VR::DS, "30");
  }
  expect_rejected(dir, series.string() + kSeed, "mixes echo times");
}

TEST(HostileNifti, ZeroVoxelSizeWithoutOrientationIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-pixdim");
  const auto file = nifti_phantom(dir, "ct.nii");
  for (int i = 1; i <= 3; ++i) patch(file, kPixdim + 4 * i, 0.0f);
  patch(file, kQformCode, std::int16_t{0});
  patch(file, kSformCode, std::int16_t{0});
  expect_rejected(dir, file.string() + kSeed, "voxel size (pixdim)");
}

TEST(HostileNifti, NanInTheAffineIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-affine");
  const auto file = nifti_phantom(dir, "ct.nii");
  patch(file, kSformCode, std::int16_t{1});
  patch(file, kSrowX, std::numeric_limits<float>::quiet_NaN());
  expect_rejected(dir, file.string() + kSeed, "affine is not finite");
}

TEST(HostileNifti, CompressedFileCutShortIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-gz");
  const auto file = nifti_phantom(dir, "ct.nii.gz");
  fs::resize_file(file, fs::file_size(file) * 3 / 4);
  expect_rejected(dir, file.string() + kSeed, "truncated");
}

// The bladder's urine NaN: before, "bladder 534.5 ml".
TEST(HostileNifti, NanVoxelsAreRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-nan-voxels");
  seg::PhantomSpec spec;
  spec.spacing_mm = 4.0;
  spec.fov_mm = {200, 200, 160};
  auto image = seg::make_phantom(spec);
  const auto mask = seg::phantom_bladder_mask(spec, *image);
  std::size_t nan = 0;
  for (std::size_t i = 0; i < image->GetLargestPossibleRegion().GetNumberOfPixels(); ++i)
    if (mask->GetBufferPointer()[i]) image->GetBufferPointer()[i] = std::nanf(""), ++nan;
  auto writer = itk::ImageFileWriter<seg::ScanImage>::New();
  writer->SetInput(image);
  writer->SetFileName((dir / "ct.nii.gz").string());
  writer->Update();
  expect_rejected(dir, (dir / "ct.nii.gz").string() + kSeed,
                  std::to_string(nan) + " voxels are not finite");
}

TEST(LabelSanity, ResultBelowTheMinimumVolumeIsRefused) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-min-volume");
  const auto series = small_series(dir, "ct");
  expect_rejected(dir, series.string() + kSeed + " --min-volume-ml 1000",
                  "less than --min-volume-ml 1000");
}

// De-identification treats UIDs as identifiers: the series goes by its key everywhere.
TEST(SeriesUid, NeverInTheSummaryManifestListingOrMessages) {
  const auto dir = vesica::test::scratch_dir("segment-hostile-uid");
  const auto series = small_series(dir, "ct");
  const auto all = seg::scan_dicom_folder(series);
  ASSERT_EQ(all.size(), 1u);
  const std::string uid = all[0].uid;
  ASSERT_GT(uid.size(), 10u);
  ASSERT_EQ(run_tool("vesica-segment",
                     series.string() + " -o " + (dir / "b.nii.gz").string() + kSeed + " --series " +
                         uid + " --report " + (dir / "s.json").string(),
                     dir),
            0)
      << read_text(dir / "stderr.txt");
  for (const char* f : {"s.json", ".vesica/s.manifest.json", "stderr.txt", "stdout.txt"}) {
    const std::string text = read_text(dir / f);
    EXPECT_EQ(text.find(uid), std::string::npos) << f;
  }
  EXPECT_NE(read_text(dir / "s.json").find(all[0].key()), std::string::npos);
  ASSERT_EQ(run_tool("vesica-segment", series.string() + " --list-series", dir), 0);
  EXPECT_EQ(read_text(dir / "stdout.txt").find(uid), std::string::npos);
  EXPECT_NE(read_text(dir / "stdout.txt").find(all[0].key()), std::string::npos);
  // The key selects the series; an unknown UID is not echoed back.
  ASSERT_EQ(run_tool("vesica-segment",
                     series.string() + " -o " + (dir / "c.nii.gz").string() + kSeed + " --series " +
                         all[0].key(),
                     dir),
            0);
  const std::string wrong = uid + ".99";
  const std::string err =
      expect_rejected(dir, series.string() + kSeed + " --series " + wrong, "no series matches");
  EXPECT_EQ(err.find(wrong), std::string::npos);
}

TEST(BadMr, NoBrightRegionNearTheSeed) {
  const auto dir = vesica::test::scratch_dir("segment-bad-mr-dark");
  const auto series = small_series(dir, "mr", 1, seg::Modality::MR);
  // Muscle beside the pelvic ring: dark on T2.
  expect_rejected(dir, series.string() + " --seed 70,10,30", "no bright (urine) region");
}

TEST(BadMr, SeedOutsideTheImage) {
  const auto dir = vesica::test::scratch_dir("segment-bad-mr-outside");
  const auto series = small_series(dir, "mr", 1, seg::Modality::MR);
  expect_rejected(dir, series.string() + " --seed 0,-15,900", "outside the image");
}
