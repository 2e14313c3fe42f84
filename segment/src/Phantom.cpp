#include "vesica/segment/Phantom.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include <itkImageRegionIteratorWithIndex.h>

namespace vesica::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFatShellMm = 15.0;   // perivesical fat around the bladder
constexpr double kRectumGapMm = 18.0;  // fat shell surface to rectum axis
constexpr double kRectumRadiusMm = 17.0, kRectumLumenMm = 11.0;
// The detrusor: hypointense between urine and fat on T2, so the MR phantom draws it. The
// CT phantom leaves it out (wall and urine differ by ~40 HU; its urine borders fat).
constexpr double kMrWallMm = 3.0;

BladderShapeSpec bladder_spec(const PhantomSpec& spec) {
  BladderShapeSpec b;
  b.shape = spec.shape;
  b.volume_ml = spec.bladder_ml;
  b.elongation = spec.elongation;
  b.neck_radius_mm = spec.neck_radius_mm;
  return b;
}

struct Anatomy {
  BladderShape bladder;
  double wall_mm = 0;
  double rectum_y = 0;  // rectum axis (runs head-feet)

  explicit Anatomy(const PhantomSpec& spec)
      : bladder(bladder_spec(spec)), wall_mm(spec.modality == Modality::MR ? kMrWallMm : 0.0) {
    rectum_y = bladder_spec(spec).center_mm[1] + bladder.semi_axes_mm()[1] + wall_mm + kFatShellMm +
               kRectumGapMm;
  }

  // Order matters: the bladder, its wall and its fat override the rest.
  Tissue tissue(double x, double y, double z) const {
    const double grows[3] = {0.0, wall_mm, wall_mm + kFatShellMm};
    switch (bladder.layer({x, y, z}, grows, 3)) {
      case 0:
        return Tissue::Urine;
      case 1:
        return Tissue::BladderWall;
      case 2:
        return Tissue::Fat;
      default:
        break;
    }
    const double body = x * x / (170.0 * 170.0) + (y - 10) * (y - 10) / (125.0 * 125.0);
    if (body > 1) return Tissue::Air;
    const double rr = x * x + (y - rectum_y) * (y - rectum_y);
    if (rr <= kRectumLumenMm * kRectumLumenMm) return Tissue::Air;
    if (rr <= kRectumRadiusMm * kRectumRadiusMm) return Tissue::Muscle;
    const double ring_outer = x * x / (135.0 * 135.0) + (y - 10) * (y - 10) / (110.0 * 110.0);
    const double ring_inner = x * x / (120.0 * 120.0) + (y - 10) * (y - 10) / (95.0 * 95.0);
    if (ring_outer <= 1 && ring_inner > 1) return Tissue::Bone;
    const double subcutaneous = x * x / (158.0 * 158.0) + (y - 10) * (y - 10) / (113.0 * 113.0);
    if (subcutaneous > 1) return Tissue::Fat;
    return Tissue::Muscle;
  }
};

// What each tissue reads in this phantom's modality.
std::array<double, kTissueCount> tissue_values(const PhantomSpec& spec) {
  std::array<double, kTissueCount> v{};
  for (int t = 0; t < kTissueCount; ++t)
    v[t] = spec.modality == Modality::CT ? ct_value_hu(static_cast<Tissue>(t))
                                         : mr_signal(static_cast<Tissue>(t), spec.mr);
  return v;
}

ScanImage::DirectionType direction_of(const PhantomSpec& spec) {
  ScanImage::DirectionType d;
  d.SetIdentity();
  if (spec.orientation == PhantomOrientation::Oblique) {
    // A gantry-tilt-like rotation about the L-R axis, then a small in-plane turn.
    const double a = 20.0 * kPi / 180.0, b = 15.0 * kPi / 180.0;
    ScanImage::DirectionType rx, rz;
    rx.SetIdentity();
    rz.SetIdentity();
    rx(1, 1) = std::cos(a), rx(1, 2) = -std::sin(a), rx(2, 1) = std::sin(a), rx(2, 2) = std::cos(a);
    rz(0, 0) = std::cos(b), rz(0, 1) = -std::sin(b), rz(1, 0) = std::sin(b), rz(1, 1) = std::cos(b);
    d = rx * rz;
  }
  if (spec.reverse_slices)
    for (int r = 0; r < 3; ++r) d(r, 2) = -d(r, 2);
  return d;
}

ScanImage::SpacingType spacing_of(const PhantomSpec& spec) {
  const std::array<double, 3> mm = phantom_spacing_mm(spec);
  ScanImage::SpacingType s;
  for (int i = 0; i < 3; ++i) s[i] = mm[i];
  return s;
}

// An empty image whose grid is centred on the patient origin.
ScanImage::Pointer make_grid(const PhantomSpec& spec) {
  ScanImage::SizeType size;
  const auto spacing = spacing_of(spec);
  const std::array<double, 3> voxels = phantom_grid_size(spec);
  for (int i = 0; i < 3; ++i) size[i] = static_cast<itk::SizeValueType>(voxels[i]);
  const auto d = direction_of(spec);
  ScanImage::PointType origin;
  for (int r = 0; r < 3; ++r) {
    origin[r] = 0;
    for (int c = 0; c < 3; ++c) origin[r] -= d(r, c) * 0.5 * (size[c] - 1) * spacing[c];
  }
  auto image = ScanImage::New();
  image->SetRegions(ScanImage::RegionType(size));
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(d);
  image->Allocate();
  return image;
}

// Samples per voxel edge: thick slices get proportionally more along the slice axis, so
// that a thin layer (the MR wall) cannot fall between the samples.
struct Sampling {
  std::array<int, 3> corners{};  // uniformity probes per axis, minus one
  std::array<int, 3> sub{};      // partial-volume sub-samples per axis
};

Sampling sampling_of(const ScanImage& image) {
  const auto& s = image.GetSpacing();
  const double finest = std::min({s[0], s[1], s[2]});
  Sampling out;
  for (int i = 0; i < 3; ++i) {
    out.corners[i] = std::max(1, static_cast<int>(std::lround(s[i] / finest)));
    out.sub[i] = 4 * out.corners[i];
  }
  return out;
}

// The tissues at the uniformity probes of one slice of voxels: a lattice on the voxels'
// faces, shared by neighbouring voxels (each probe is evaluated once, not once per voxel).
class SliceProbes {
 public:
  SliceProbes(const Anatomy& anatomy, const ScanImage& image, const Sampling& sampling,
              itk::IndexValueType k)
      : m_(sampling.corners) {
    const auto size = image.GetLargestPossibleRegion().GetSize();
    nx_ = static_cast<std::size_t>(size[0]) * m_[0] + 1;
    ny_ = static_cast<std::size_t>(size[1]) * m_[1] + 1;
    tissues_.resize(nx_ * ny_ * (m_[2] + 1));
    std::size_t n = 0;
    for (int t = 0; t <= m_[2]; ++t)
      for (std::size_t y = 0; y < ny_; ++y)
        for (std::size_t x = 0; x < nx_; ++x) {
          itk::ContinuousIndex<double, 3> c;
          c[0] = double(x) / m_[0] - 0.5;
          c[1] = double(y) / m_[1] - 0.5;
          c[2] = double(k) - 0.5 + double(t) / m_[2];
          ScanImage::PointType p;
          image.TransformContinuousIndexToPhysicalPoint(c, p);
          tissues_[n++] = anatomy.tissue(p[0], p[1], p[2]);
        }
  }

  // Whether every probe of voxel (i, j) of this slice reads tissue c.
  bool uniform(itk::IndexValueType i, itk::IndexValueType j, Tissue c) const {
    for (int t = 0; t <= m_[2]; ++t)
      for (int y = 0; y <= m_[1]; ++y)
        for (int x = 0; x <= m_[0]; ++x)
          if (tissues_[(t * ny_ + j * m_[1] + y) * nx_ + i * m_[0] + x] != c) return false;
    return true;
  }

 private:
  std::array<int, 3> m_;
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<Tissue> tissues_;
};

// Mean value over one voxel: the centre's tissue value when the centre and the probes on
// the voxel's faces agree (no border inside), else the mean of sub-samples (partial-volume
// effect).
double voxel_value(const Anatomy& anatomy, const std::array<double, kTissueCount>& values,
                   const Sampling& sampling, const SliceProbes& probes, const ScanImage& image,
                   const itk::Index<3>& index) {
  const auto& d = image.GetDirection();
  const auto& s = image.GetSpacing();
  ScanImage::PointType centre;
  image.TransformIndexToPhysicalPoint(index, centre);
  auto at = [&](double u, double v, double w) {  // offsets in voxels along the grid axes
    double p[3];
    for (int r = 0; r < 3; ++r)
      p[r] = centre[r] + d(r, 0) * u * s[0] + d(r, 1) * v * s[1] + d(r, 2) * w * s[2];
    return anatomy.tissue(p[0], p[1], p[2]);
  };
  const Tissue c = at(0, 0, 0);
  if (probes.uniform(index[0], index[1], c)) return values[static_cast<int>(c)];
  const auto& n = sampling.sub;
  double sum = 0;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k)
        sum += values[static_cast<int>(
            at((i + 0.5) / n[0] - 0.5, (j + 0.5) / n[1] - 0.5, (k + 0.5) / n[2] - 0.5))];
  return sum / (n[0] * n[1] * n[2]);
}

// Calls f(k) for every slice index k, the slices shared out among the cores.
template <class F>
void for_each_slice_in_parallel(itk::SizeValueType slices, const F& f) {
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (itk::IndexValueType k = w; k < static_cast<itk::IndexValueType>(slices); k += workers)
        f(k);
    });
  for (auto& t : threads) t.join();
}

// MR: the coil's smooth sensitivity, then Rician noise (the magnitude of a complex signal
// whose two channels carry Gaussian noise), so that air reads a Rayleigh floor.
void add_mr_acquisition(const PhantomSpec& spec, ScanImage& image) {
  const double sigma = spec.mr.noise_fraction * mr_signal(Tissue::Urine, spec.mr);
  std::mt19937 rng(spec.rng_seed);
  std::normal_distribution<double> noise(0.0, sigma > 0 ? sigma : 1.0);
  itk::ImageRegionIteratorWithIndex<ScanImage> it(&image, image.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    ScanImage::PointType p;
    image.TransformIndexToPhysicalPoint(it.GetIndex(), p);
    double v = it.Get() * mr_bias_field(spec, {p[0], p[1], p[2]});
    if (sigma > 0) {
      const double re = v + noise(rng), im = noise(rng);
      v = std::sqrt(re * re + im * im);
    }
    it.Set(static_cast<float>(v));
  }
}

void add_ct_noise(const PhantomSpec& spec, ScanImage& image) {
  if (!(spec.noise_hu > 0)) return;
  std::mt19937 rng(spec.rng_seed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(spec.noise_hu));
  float* buffer = image.GetBufferPointer();
  const std::size_t n = image.GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t v = 0; v < n; ++v) buffer[v] += noise(rng);
}

}  // namespace

PhantomTruth phantom_truth(const PhantomSpec& spec) {
  const BladderShape shape(bladder_spec(spec));
  PhantomTruth t;
  t.bladder_volume_ml = shape.volume_ml();
  t.bladder_center_mm = shape.centroid_mm();
  t.bladder_semi_axes_mm = shape.semi_axes_mm();
  return t;
}

double mr_bias_field(const PhantomSpec& spec, const std::array<double, 3>& p) {
  const double x = p[0] / (0.5 * spec.fov_mm[0]), y = p[1] / (0.5 * spec.fov_mm[1]),
               z = p[2] / (0.5 * spec.fov_mm[2]);
  // |q| <= 0.5 + 0.3 + 0.2 = 1 inside the field of view; clamped beyond its corners.
  const double q = std::clamp(0.5 * y + 0.3 * z + 0.2 * (2 * x * x - 1), -1.0, 1.0);
  return 1.0 + spec.mr.bias_fraction * q;
}

ScanImage::Pointer make_phantom(const PhantomSpec& spec) {
  const Anatomy anatomy(spec);
  const auto values = tissue_values(spec);
  auto image = make_grid(spec);
  const Sampling sampling = sampling_of(*image);
  const auto size = image->GetLargestPossibleRegion().GetSize();
  float* buffer = image->GetBufferPointer();
  const std::size_t slice = size[0] * size[1];
  for_each_slice_in_parallel(size[2], [&](itk::IndexValueType k) {
    const SliceProbes probes(anatomy, *image, sampling, k);
    for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); ++j)
      for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); ++i)
        buffer[k * slice + j * size[0] + i] =
            static_cast<float>(voxel_value(anatomy, values, sampling, probes, *image, {{i, j, k}}));
  });
  if (spec.modality == Modality::MR)
    add_mr_acquisition(spec, *image);
  else
    add_ct_noise(spec, *image);
  return image;
}

LabelImage::Pointer phantom_bladder_mask(const PhantomSpec& spec, const ScanImage& like) {
  const BladderShape bladder(bladder_spec(spec));
  auto mask = LabelImage::New();
  mask->CopyInformation(&like);
  mask->SetRegions(like.GetLargestPossibleRegion());
  mask->Allocate();
  itk::ImageRegionIteratorWithIndex<LabelImage> it(mask, mask->GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    LabelImage::PointType p;
    mask->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(bladder.inside({p[0], p[1], p[2]}) ? 1 : 0);
  }
  return mask;
}

DicomSeriesHeader phantom_series_header(const PhantomSpec& spec) {
  DicomSeriesHeader h;
  h.modality = spec.modality;
  if (spec.modality == Modality::CT) return h;
  const MrAcquisition& a = spec.mr;
  constexpr double kProtonMhzPerTesla = 42.577478;  // gyromagnetic ratio of 1H / 2 pi
  h.series_description = std::string("VESICA phantom T2 TSE") + (a.fat_suppression ? " FS" : "") +
                         (spec.orientation == PhantomOrientation::Oblique ? " oblique" : " axial");
  const double slice = spacing_of(spec)[2];
  h.attributes = {
      {"0018|0020", "SE"},                                    // ScanningSequence
      {"0018|0021", "SK"},                                    // SequenceVariant
      {"0018|0022", a.fat_suppression ? "FS" : ""},           // ScanOptions
      {"0018|0023", "2D"},                                    // MRAcquisitionType
      {"0018|0080", dicom_decimals({a.repetition_time_ms})},  // RepetitionTime
      {"0018|0081", dicom_decimals({a.echo_time_ms})},        // EchoTime
      {"0018|0083", "1"},                                     // NumberOfAverages
      {"0018|0084", dicom_decimals({kProtonMhzPerTesla * a.field_strength_t})},
      {"0018|0085", "1H"},                                  // ImagedNucleus
      {"0018|0086", "1"},                                   // EchoNumbers
      {"0018|0087", dicom_decimals({a.field_strength_t})},  // MagneticFieldStrength
      {"0018|0088", dicom_decimals({slice})},               // SpacingBetweenSlices
      {"0018|0091", "16"},                                  // EchoTrainLength
      {"0018|1314", "90"},                                  // FlipAngle
  };
  return h;
}

}  // namespace vesica::segment
