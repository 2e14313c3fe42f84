#include "vesica/io/RegionsSidecar.h"

#include <cmath>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>
#include <nlohmann/json.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/JsonFile.h"
#include "vesica/core/Regions.h"
#include "vesica/core/SideOutputNames.h"

namespace vesica::io {
namespace {

nlohmann::json parse_json(const std::filesystem::path& sidecar) {
  const nlohmann::json j = read_json_file(sidecar, kMaxMeshFileBytes).value_or(nullptr);
  if (j.is_discarded()) fail(sidecar.string(), "not valid JSON");
  return j;
}

Eigen::VectorXi tags_of(const nlohmann::json& j, const std::filesystem::path& sidecar) {
  if (!j.is_object() || !j.contains("region") || !j.at("region").is_array())
    fail(sidecar.string(), "no \"region\" array of tags");
  const auto& tags = j.at("region");
  Eigen::VectorXi region(static_cast<Eigen::Index>(tags.size()));
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (!tags[i].is_number_integer())
      fail(sidecar.string(), "region tag " + std::to_string(i) + " is not an integer");
    region(static_cast<Eigen::Index>(i)) = tags[i].get<int>();
  }
  return region;
}

Eigen::MatrixXd centroids_of(const nlohmann::json& j, Eigen::Index tag_count,
                             const std::filesystem::path& sidecar) {
  if (!j.contains("centroids_mm")) return Eigen::MatrixXd(0, 3);
  const auto& flat = j.at("centroids_mm");
  if (!flat.is_array() || static_cast<Eigen::Index>(flat.size()) != 3 * tag_count)
    fail(sidecar.string(),
         "\"centroids_mm\" must hold x,y,z for each of the " + std::to_string(tag_count) + " tags");
  Eigen::MatrixXd c(tag_count, 3);
  for (Eigen::Index i = 0; i < tag_count; ++i)
    for (int d = 0; d < 3; ++d) {
      const auto& v = flat[static_cast<std::size_t>(3 * i + d)];
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        fail(sidecar.string(), "centroid " + std::to_string(i) + " is not three finite numbers");
      c(i, d) = v.get<double>();
    }
  return c;
}

}  // namespace

std::filesystem::path regions_sidecar_path(const std::filesystem::path& surface_path) {
  return regions_sidecar_name(surface_path.string());
}

void write_regions_sidecar(const TaggedSurface& surface, const std::filesystem::path& sidecar) {
  nlohmann::json names = nlohmann::json::object();
  for (Region r : kAllRegions) names[std::to_string(static_cast<int>(r))] = region_name(r);
  const Eigen::VectorXi tags =
      surface.has_regions()
          ? surface.region
          : Eigen::VectorXi::Constant(surface.triangles.rows(), static_cast<int>(Region::Wall));
  // Row-major x,y,z per triangle, so that tags can follow triangles through outside edits.
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> centroids =
      triangle_centroids(surface.points_mm, surface.triangles);
  const nlohmann::json j = {
      {"units", "mm"},
      {"triangle_count", surface.triangles.rows()},
      {"region_names", names},
      {"region", std::vector<int>(tags.data(), tags.data() + tags.size())},
      {"centroids_mm", std::vector<double>(centroids.data(), centroids.data() + centroids.size())}};
  write_text_atomically(sidecar, j.dump(1) + "\n");
}

std::optional<RegionsSidecar> read_regions_sidecar(const std::filesystem::path& sidecar) {
  if (!std::filesystem::exists(sidecar)) return std::nullopt;
  const nlohmann::json j = parse_json(sidecar);
  RegionsSidecar out;
  out.region = tags_of(j, sidecar);
  out.centroids = centroids_of(j, out.region.size(), sidecar);
  return out;
}

Eigen::VectorXi retag_by_nearest_centroid(const Eigen::MatrixXd& recorded_centroids,
                                          const Eigen::VectorXi& recorded_region,
                                          const TaggedSurface& surface) {
  vtkNew<vtkPoints> recorded;
  recorded->SetDataTypeToDouble();
  recorded->SetNumberOfPoints(recorded_centroids.rows());
  for (Eigen::Index i = 0; i < recorded_centroids.rows(); ++i)
    recorded->SetPoint(i, recorded_centroids(i, 0), recorded_centroids(i, 1),
                       recorded_centroids(i, 2));
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(recorded);
  vtkNew<vtkStaticPointLocator> locator;  // a bucket grid: the search is O(M log N), not O(M N)
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  const Eigen::MatrixXd centroids = triangle_centroids(surface.points_mm, surface.triangles);
  Eigen::VectorXi region(surface.triangles.rows());
  for (Eigen::Index f = 0; f < centroids.rows(); ++f) {
    const double x[3] = {centroids(f, 0), centroids(f, 1), centroids(f, 2)};
    region(f) = recorded_region(locator->FindClosestPoint(x));
  }
  return region;
}

}  // namespace vesica::io
