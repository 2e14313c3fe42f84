// The MR phantom against what it promises (spin-echo contrast from the header's TE/TR,
// a +-30 % bias field, Rician noise, thick and oblique slices, an MR DICOM header without
// patient fields) and the N4 correction against the phantom's bias-free image.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <gdcmReader.h>

#include "SegmentTestHelpers.h"
#include "vesica/segment/BiasFieldCorrection.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/Phantom.h"
#include "vesica/segment/VolumeReader.h"

namespace fs = std::filesystem;
namespace seg = vesica::segment;

namespace {

seg::PhantomSpec mr_spec() {
  seg::PhantomSpec spec;
  spec.modality = seg::Modality::MR;
  spec.spacing_mm = 3.0;
  spec.fov_mm = {360, 300, 150};
  return spec;
}

// Standard deviation of log(a / b) over voxels where b > floor.
double log_ratio_spread(const seg::ScanImage& a, const seg::ScanImage& b, double floor) {
  const float* pa = a.GetBufferPointer();
  const float* pb = b.GetBufferPointer();
  const std::size_t n = a.GetLargestPossibleRegion().GetNumberOfPixels();
  double sum = 0, sum2 = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(pb[i] > floor) || !(pa[i] > 0)) continue;
    const double r = std::log(pa[i] / pb[i]);
    sum += r;
    sum2 += r * r;
    ++count;
  }
  const double mean = sum / count;
  return std::sqrt(std::max(0.0, sum2 / count - mean * mean));
}

}  // namespace

TEST(BiasFieldCorrection, RemovesMostOfTheCoilsThirtyPercentField) {
  seg::PhantomSpec spec = mr_spec();
  spec.mr.noise_fraction = 0;
  const auto biased = seg::make_phantom(spec);
  spec.mr.bias_fraction = 0;
  const auto flat = seg::make_phantom(spec);
  const double muscle = seg::mr_signal(seg::Tissue::Muscle, spec.mr);
  const seg::MrParams defaults;
  const auto field = seg::estimate_bias_field(*biased, defaults, "test");
  const auto corrected = seg::remove_bias(*biased, *field.log_bias, 1.0);
  const double before = log_ratio_spread(*biased, *flat, 0.5 * muscle);
  const double after = log_ratio_spread(*corrected, *flat, 0.5 * muscle);
  RecordProperty("log_spread_before", std::to_string(before));
  RecordProperty("log_spread_after", std::to_string(after));
  EXPECT_GT(before, 0.05);  // the field is there: +-30 % over the field of view
  EXPECT_LT(after, 0.2 * before);
}

// Signals hand-computed from S = 1300 * PD * (1 - exp(-TR/T1)) * exp(-TE/T2) with the
// tissue table of docs/segment.md, TE 100 ms, TR 4500 ms.
TEST(MrPhantom, TissueContrastFollowsTheSpinEchoEquation) {
  seg::MrAcquisition a;
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Urine, a), 971.000, 1e-3);
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::BladderWall, a), 246.468, 1e-3);
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Muscle, a), 99.339, 1e-3);
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Fat, a), 638.230, 1e-3);
  EXPECT_DOUBLE_EQ(seg::mr_signal(seg::Tissue::Air, a), 0.0);
  a.fat_suppression = true;
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Fat, a), 31.911, 1e-3);
  a.echo_time_ms = 150;  // a longer echo darkens short-T2 muscle far more than urine
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Urine, a), 918.527, 1e-3);
  EXPECT_NEAR(seg::mr_signal(seg::Tissue::Muscle, a), 31.886, 1e-3);
  // The image reads it: urine at the bladder's centre without bias and noise.
  seg::PhantomSpec spec = mr_spec();
  spec.mr.noise_fraction = 0;
  spec.mr.bias_fraction = 0;
  const auto image = seg::make_phantom(spec);
  seg::ScanImage::PointType c;
  for (int i = 0; i < 3; ++i) c[i] = seg::phantom_truth(spec).bladder_center_mm[i];
  seg::ScanImage::IndexType k;
  ASSERT_TRUE(image->TransformPhysicalPointToIndex(c, k));
  EXPECT_NEAR(image->GetPixel(k), 971.0, 1e-3);
}

// 1 + 0.3 q, q = 0.5 y + 0.3 z + 0.2 (2 x^2 - 1) in half fields of view (hand-evaluated).
TEST(MrPhantom, BiasFieldSpansPlusMinusThirtyPercentAcrossTheView) {
  const seg::PhantomSpec spec = mr_spec();  // half field of view 180, 150, 75 mm
  EXPECT_NEAR(seg::mr_bias_field(spec, {0, 0, 0}), 0.94, 1e-12);
  EXPECT_NEAR(seg::mr_bias_field(spec, {180, 150, 75}), 1.3, 1e-12);
  EXPECT_NEAR(seg::mr_bias_field(spec, {0, -150, -75}), 0.7, 1e-12);
  EXPECT_NEAR(seg::mr_bias_field(spec, {90, 75, 0}), 1.0 + 0.3 * (0.25 + 0.2 * (-0.5)), 1e-12);
  // The image carries it: biased / unbiased = the field at the voxel centre.
  seg::PhantomSpec flat_spec = spec;
  flat_spec.mr.noise_fraction = 0;
  seg::PhantomSpec biased_spec = flat_spec;
  flat_spec.mr.bias_fraction = 0;
  const auto flat = seg::make_phantom(flat_spec);
  const auto biased = seg::make_phantom(biased_spec);
  // Urine at the bladder's centre, and muscle beside the pelvic ring.
  for (const std::array<double, 3> at : {std::array<double, 3>{0, -15, -10}, {100, 10, 30}}) {
    seg::ScanImage::PointType p;
    for (int i = 0; i < 3; ++i) p[i] = at[i];
    itk::Index<3> k;
    ASSERT_TRUE(flat->TransformPhysicalPointToIndex(p, k));
    flat->TransformIndexToPhysicalPoint(k, p);
    ASSERT_GT(flat->GetPixel(k), 50.0f);  // tissue, not air
    EXPECT_NEAR(biased->GetPixel(k) / flat->GetPixel(k),
                seg::mr_bias_field(spec, {p[0], p[1], p[2]}), 1e-5);
  }
}

// Magnitude images: air reads the Rayleigh mean sigma * sqrt(pi / 2); bright urine
// (SNR 40) scatters with sigma about its value.
TEST(MrPhantom, RicianNoiseHasItsRayleighFloorInAir) {
  seg::PhantomSpec spec = mr_spec();
  spec.mr.bias_fraction = 0;
  const auto noisy = seg::make_phantom(spec);
  spec.mr.noise_fraction = 0;
  const auto clean = seg::make_phantom(spec);
  const double sigma = 0.025 * 971.0;
  const double urine = seg::mr_signal(seg::Tissue::Urine, spec.mr);
  double air_sum = 0, urine_sum2 = 0;
  std::size_t air = 0, inside = 0;
  const std::size_t n = noisy->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i) {
    const double c = clean->GetBufferPointer()[i], v = noisy->GetBufferPointer()[i];
    if (c == 0) air_sum += v, ++air;
    if (std::abs(c - urine) < 1e-3) urine_sum2 += (v - c) * (v - c), ++inside;
  }
  ASSERT_GT(air, 10000u);
  ASSERT_GT(inside, 5000u);
  EXPECT_NEAR(air_sum / air, sigma * 1.2533141, 0.02 * sigma);
  EXPECT_NEAR(std::sqrt(urine_sum2 / inside), sigma, 0.03 * sigma);
}

// Through the executable: an MR DICOM series with its acquisition in the header and every
// patient attribute (group 0010) empty (DICOM requires name, ID, birth date and sex to be
// present, and allows them empty), thick oblique slices read back with their geometry, and
// the exact volume in the report.
TEST(MrPhantom, SeriesCarriesTheAcquisitionAndNoPatientField) {
  const auto dir = vesica::test::scratch_dir("mr-phantom-header");
  ASSERT_EQ(vesica::test::run_tool(
                "vesica-phantom",
                "-o " + (dir / "mr").string() +
                    " --modality mr --fat-suppression --echo-time-ms 90 --repetition-time-ms 5000"
                    " --field-strength-t 3 --spacing-mm 2 --slice-spacing-mm 4"
                    " --fov-mm 200,180,120 --orientation oblique --bladder-ml 250 --report " +
                    (dir / "phantom.json").string(),
                dir),
            0)
      << vesica::test::read_text(dir / "stderr.txt");
  const std::string report = vesica::test::read_text(dir / "phantom.json");
  EXPECT_NE(report.find("\"bladder_volume_ml\": 250.0"), std::string::npos) << report;
  EXPECT_EQ(report.find("uid"), std::string::npos) << report;
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir / "mr")) {
    if (e.path().extension() != ".dcm") continue;  // .vesica-output: the folder is vesica's
    gdcm::Reader r;
    r.SetFileName(e.path().c_str());
    ASSERT_TRUE(r.Read());
    const auto& ds = r.GetFile().GetDataSet();
    auto text = [&ds](std::uint16_t g, std::uint16_t el) {
      const auto& de = ds.GetDataElement(gdcm::Tag(g, el));
      if (de.IsEmpty()) return std::string();
      std::string v(de.GetByteValue()->GetPointer(), de.GetByteValue()->GetLength());
      return v.substr(0, v.find_last_not_of(std::string(" \0", 2)) + 1);
    };
    EXPECT_EQ(text(0x0008, 0x0060), "MR");
    EXPECT_EQ(text(0x0008, 0x0016), "1.2.840.10008.5.1.4.1.1.4");  // MR Image Storage
    EXPECT_EQ(text(0x0018, 0x0081), "90");
    EXPECT_EQ(text(0x0018, 0x0080), "5000");
    EXPECT_EQ(text(0x0018, 0x0087), "3");
    EXPECT_EQ(text(0x0018, 0x0022), "FS");
    EXPECT_EQ(text(0x0018, 0x0088), "4");
    for (const auto& de : ds.GetDES())
      if (de.GetTag().GetGroup() == 0x0010) {
        EXPECT_TRUE(de.IsEmpty()) << de.GetTag();
      }
    ++files;
  }
  EXPECT_EQ(files, 30u);  // 120 mm / 4 mm slices
  const auto v = seg::read_volume(dir / "mr", "");
  EXPECT_EQ(v.modality, "MR");
  EXPECT_DOUBLE_EQ(v.echo_time_ms, 90.0);
  EXPECT_NEAR(v.image->GetSpacing()[0], 2.0, 1e-9);
  EXPECT_NEAR(v.image->GetSpacing()[2], 4.0, 1e-6);
  EXPECT_NEAR(v.image->GetDirection()(2, 2), std::cos(20.0 * M_PI / 180.0), 1e-6);
}
