// The distributed assembly's decomposition, checked in one process: a two-region mesh split
// into 1–4 parts (mesh/partition.hpp), each part's problem assembled on its own view of the mesh
// (physics/assembly_scope.hpp), and the parts' contributions added by the rules of
// SubdomainDofs. The sums must be the whole mesh's residual, Jacobian, ∂F/∂t, reactions, fluid
// rates and volume change, computed independently by the one-process problem, to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "../common/box_mesh.hpp"
#include "../common/every_condition.hpp"
#include "biphasic/assembly/subdomain_dofs.hpp"
#include "biphasic/mesh/partition.hpp"
#include "biphasic/physics/assembly_scope.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {
namespace {

/// A box in two material regions (below and above z = 0.6 mm), long enough that with three or
/// four parts some part does not even touch part 0.
Mesh test_mesh() {
  Mesh mesh = test::box_mesh({2, 2, 6}, {1.0, 0.8, 1.8});
  mesh.region_names = {"lower", "upper"};
  mesh.tet_region.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    double z = 0.0;
    for (int c = 0; c < 4; ++c)
      z += 0.25 * mesh.nodes[static_cast<std::size_t>(mesh.tets[t][c])][2];
    mesh.tet_region[t] = z < 0.6 ? 0 : 1;
  }
  return mesh;
}

/// A section rectangle (axis, lateral, bottom, top) for a two-dimensional model.
SectionMesh test_section() {
  SectionRectangleSpec spec;
  spec.width = 1.2;
  spec.height = 1.8;
  spec.nr = 3;
  spec.nz = 6;
  SectionMesh mesh = generate_section_rectangle(spec);
  mesh.region_names = {"lower", "upper"};
  mesh.triangle_region.assign(mesh.triangles.size(), 0);
  return mesh;
}

/// every_condition with a stiffer, more permeable upper region.
Config two_region_condition() {
  Config cfg = test::every_condition();
  RegionConfig upper{"upper", cfg.material};
  upper.material.set("mu", 2.0);
  upper.material.set("permeability", 4e-2);
  cfg.regions = {upper};
  return cfg;
}

void add_volume_loads(BiphasicProblem& problem) {
  problem.set_body_force(
      [](const Vec3& X, double t) { return Vec3(0.01 * t, -0.02 * X(2), 0.03); });
  problem.set_fluid_source([](const Vec3& X, double t) { return 1e-3 * (X(0) + t); });
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(Partition, CoversEveryElementOnceAndNumbersEveryUnknownOnce) {
  const Mesh mesh = test_mesh();
  for (int parts = 1; parts <= 4; ++parts) {
    SCOPED_TRACE(parts);
    const MeshPartition p = partition_mesh(mesh, parts);
    std::vector<int> owned_count(mesh.tets.size(), 0);
    for (int r = 0; r < parts; ++r) {
      const Subdomain sub = extract_subdomain(mesh, p, r);
      EXPECT_NO_THROW(check_mesh(sub.mesh));
      Index owned = 0;
      for (std::size_t e = 0; e < sub.global_element.size(); ++e)
        if (sub.element_owned[e]) {
          ++owned_count[static_cast<std::size_t>(sub.global_element[e])];
          ++owned;
        }
      EXPECT_GT(owned, 0);
      // An owned node is touched by an owned element (its owner assembles its rows).
      for (std::size_t m = 0; m < sub.global_node.size(); ++m)
        if (sub.node_owned[m]) {
          EXPECT_TRUE(sub.node_touched[m]) << "node " << sub.global_node[m];
        }
    }
    EXPECT_TRUE(std::all_of(owned_count.begin(), owned_count.end(), [](int c) { return c == 1; }));
    // The rank-major numbering is a bijection onto [0, N), each part one contiguous range.
    const PartitionedNumbering num = number_unknowns(mesh, p);
    const std::vector<Index> map = rank_major_of_whole(mesh.num_vertices, num);
    EXPECT_EQ(num.size(), static_cast<Index>(map.size()));
    std::vector<Index> sorted = map;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<Index>(i));
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      const auto r = static_cast<std::size_t>(p.node_owner[static_cast<std::size_t>(n)]);
      EXPECT_GE(num.u_base[static_cast<std::size_t>(n)], num.offset[r]);
      EXPECT_LT(num.u_base[static_cast<std::size_t>(n)], num.offset[r + 1]);
    }
  }
}

TEST(Partition, SplitsASectionAsItSplitsTetrahedra) {
  const SectionMesh mesh = test_section();
  for (int parts = 1; parts <= 4; ++parts) {
    SCOPED_TRACE(parts);
    const MeshPartition p = partition_mesh(mesh, parts);
    std::vector<int> owned_count(mesh.triangles.size(), 0);
    Index segments = 0;
    for (int r = 0; r < parts; ++r) {
      const SectionSubdomain sub = extract_subdomain(mesh, p, r);
      EXPECT_NO_THROW(check_section_mesh(sub.mesh));
      for (std::size_t e = 0; e < sub.global_element.size(); ++e) {
        if (sub.element_owned[e]) ++owned_count[static_cast<std::size_t>(sub.global_element[e])];
        // The part's triangles are the whole mesh's, renumbered.
        for (int a = 0; a < 6; ++a)
          ASSERT_EQ(sub.global_node[static_cast<std::size_t>(sub.mesh.triangles[e][a])],
                    mesh.triangles[static_cast<std::size_t>(sub.global_element[e])][a]);
      }
      for (const SectionBoundary& b : sub.mesh.boundaries)
        segments += static_cast<Index>(b.segments.size());
    }
    EXPECT_TRUE(std::all_of(owned_count.begin(), owned_count.end(), [](int c) { return c == 1; }));
    Index whole_segments = 0;
    for (const SectionBoundary& b : mesh.boundaries)
      whole_segments += static_cast<Index>(b.segments.size());
    // Every segment is in some part (in two when both parts hold its triangle).
    EXPECT_GE(segments, whole_segments);
    // Two displacements per node, one pressure per vertex, numbered once each.
    const PartitionedNumbering num = number_unknowns(mesh, p);
    EXPECT_EQ(num.components, 2);
    EXPECT_EQ(num.size(), 2 * mesh.num_nodes() + mesh.num_vertices);
    std::vector<Index> sorted = rank_major_of_whole(mesh.num_vertices, num);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<Index>(i));
  }
}

TEST(Partition, RefusesMorePartsThanElements) {
  const Mesh mesh = test::box_mesh({1, 1, 1}, {1.0, 1.0, 1.0});
  EXPECT_THROW(partition_mesh(mesh, 7), std::invalid_argument);
  EXPECT_THROW(partition_mesh(mesh, 0), std::invalid_argument);
}

/// every_section_condition with the two regions of two_region_condition.
Config section_condition(ModelKind model) {
  Config cfg = test::every_section_condition(model);
  cfg.regions = two_region_condition().regions;
  return cfg;
}

template <class Problem>
void add_section_loads(Problem& problem) {
  problem.set_body_force([](const Vec3& X, double t) { return Vec3(0.01 * t, -0.02 * X(1), 0.0); });
  problem.set_fluid_source([](const Vec3& X, double t) { return 1e-3 * (X(0) + t); });
}

/// The meshes a part's problem is built on: tetrahedra, or a section.
enum class Scene { Tetrahedra, PlaneStrain, Axisymmetric };

std::string scene_name(Scene s) {
  return s == Scene::Tetrahedra    ? "tetrahedra"
         : s == Scene::PlaneStrain ? "plane_strain"
                                   : "axisymmetric";
}

/// The whole problem and every part's problem at one random state (parameter: the scene and
/// the number of parts). Every check below is one of the BiphasicModel interface, so that it
/// holds for the tetrahedral and the section problems alike.
class SubdomainAssembly : public ::testing::TestWithParam<std::tuple<Scene, int>> {
 protected:
  void SetUp() override {
    const auto [scene, parts] = GetParam();
    scene_ = scene;
    if (scene == Scene::Tetrahedra) {
      mesh_ = test_mesh();
      reaction_names_ = {"z0", "z1", "x0"};
      split(mesh_, parts, mesh_.tet_region);
    } else {
      section_ = test_section();
      reaction_names_ = {"bottom", "top"};
      split(section_, parts, section_.triangle_region);
    }
  }

  /// The whole problem on `whole`, then each part's: `regions` (the whole mesh's per element)
  /// made the upper region on part 0's elements when there are several parts, so that every
  /// part holds one region only, and its scales (the stiffest material's) must still be the
  /// whole mesh's.
  template <class AnyMesh>
  void split(AnyMesh& whole, int parts, std::vector<int>& regions) {
    const MeshPartition partition = partition_mesh(whole, parts);
    if (parts > 1)
      for (std::size_t e = 0; e < regions.size(); ++e)
        regions[e] = partition.element_part[e] == 0 ? 1 : 0;
    whole_ = make_problem(whole, AssemblyScope{});
    test::random_state(*whole_, kTime, 11, y_, ydot_);

    numbering_ = number_unknowns(whole, partition);
    map_ = rank_major_of_whole(whole.num_vertices, numbering_);
    const std::size_t n = y_.size();
    std::vector<double> yp(n), ydotp(n);
    for (std::size_t i = 0; i < n; ++i) {
      yp[static_cast<std::size_t>(map_[i])] = y_[i];
      ydotp[static_cast<std::size_t>(map_[i])] = ydot_[i];
    }
    for (int r = 0; r < parts; ++r) {
      auto sub = std::make_unique<decltype(extract_subdomain(whole, partition, r))>(
          extract_subdomain(whole, partition, r));
      if constexpr (std::is_same_v<AnyMesh, Mesh>)
        problems_.push_back(make_problem(sub->mesh, subdomain_scope(whole, *sub)));
      else
        problems_.push_back(make_problem(sub->mesh, subdomain_scope(whole, *sub, section_model())));
      BiphasicModel& local = *problems_.back();
      dofs_.emplace_back(*sub, numbering_, local.pattern(), local.constrained());
      const SubdomainDofs& dofs = dofs_.back();
      std::vector<double> yl(static_cast<std::size_t>(local.size())), ydl = yl;
      for (Index i = 0; i < local.size(); ++i) {
        yl[static_cast<std::size_t>(i)] = yp[static_cast<std::size_t>(dofs.global(i))];
        ydl[static_cast<std::size_t>(i)] = ydotp[static_cast<std::size_t>(dofs.global(i))];
      }
      part_y_.push_back(std::move(yl));
      part_ydot_.push_back(std::move(ydl));
      keep(std::move(sub));
    }
  }

  void keep(std::unique_ptr<Subdomain> sub) { tet_parts_.push_back(std::move(sub)); }
  void keep(std::unique_ptr<SectionSubdomain> sub) { section_parts_.push_back(std::move(sub)); }
  SectionModel section_model() const {
    return scene_ == Scene::PlaneStrain ? SectionModel::PlaneStrain : SectionModel::Axisymmetric;
  }
  std::unique_ptr<BiphasicModel> make_problem(const Mesh& mesh, AssemblyScope scope) {
    config_ = two_region_condition();
    auto p = std::make_unique<BiphasicProblem>(mesh, config_, std::move(scope));
    add_volume_loads(*p);
    return p;
  }
  std::unique_ptr<BiphasicModel> make_problem(const SectionMesh& mesh, AssemblyScope scope) {
    config_ = section_condition(scene_ == Scene::PlaneStrain ? ModelKind::PlaneStrain
                                                             : ModelKind::Axisymmetric);
    auto p = std::make_unique<SectionProblem>(mesh, section_model(), config_, std::move(scope));
    add_section_loads(*p);
    return p;
  }

  /// Adds each part's contributing rows of a local vector (made by `local_vector`) into a vector
  /// of the whole system, returned in the serial layout.
  template <class LocalVector>
  std::vector<double> summed(LocalVector local_vector) {
    std::vector<double> partitioned(y_.size(), 0.0);
    for (std::size_t r = 0; r < problems_.size(); ++r) {
      std::vector<double> F(static_cast<std::size_t>(problems_[r]->size()));
      local_vector(r, F);
      const SubdomainDofs& dofs = dofs_[r];
      for (Index i = 0; i < dofs.size(); ++i)
        if (dofs.contributes(i))
          partitioned[static_cast<std::size_t>(dofs.global(i))] += F[static_cast<std::size_t>(i)];
    }
    std::vector<double> serial(y_.size());
    for (std::size_t i = 0; i < y_.size(); ++i)
      serial[i] = partitioned[static_cast<std::size_t>(map_[i])];
    return serial;
  }

  static constexpr double kTime = 1.3;
  Scene scene_ = Scene::Tetrahedra;
  Mesh mesh_;
  SectionMesh section_;
  Config config_;
  std::vector<std::string> reaction_names_;
  std::unique_ptr<BiphasicModel> whole_;
  std::vector<double> y_, ydot_;
  PartitionedNumbering numbering_;
  std::vector<Index> map_;
  std::vector<std::unique_ptr<Subdomain>> tet_parts_;  ///< the parts (their meshes in use)
  std::vector<std::unique_ptr<SectionSubdomain>> section_parts_;
  std::vector<std::unique_ptr<BiphasicModel>> problems_;
  std::vector<SubdomainDofs> dofs_;
  std::vector<std::vector<double>> part_y_, part_ydot_;  ///< per part, its local state
};

TEST_P(SubdomainAssembly, ResidualAndTimeDerivativeSumToTheWholeMesh) {
  std::vector<double> F(y_.size()), dFdt(y_.size());
  whole_->residual(kTime, y_.data(), ydot_.data(), F.data());
  whole_->time_derivative(kTime, dFdt.data());
  const std::vector<double> sum = summed([&](std::size_t r, std::vector<double>& out) {
    problems_[r]->residual(kTime, part_y_[r].data(), part_ydot_[r].data(), out.data());
  });
  const std::vector<double> sum_dt = summed([&](std::size_t r, std::vector<double>& out) {
    problems_[r]->time_derivative(kTime, out.data());
  });
  const double scale = max_abs(F), scale_dt = max_abs(dFdt);
  ASSERT_GT(scale, 0.0);
  ASSERT_GT(scale_dt, 0.0);
  for (std::size_t i = 0; i < F.size(); ++i) {
    ASSERT_NEAR(sum[i], F[i], 1e-12 * scale) << "row " << i;
    ASSERT_NEAR(sum_dt[i], dFdt[i], 1e-12 * scale_dt) << "row " << i;
  }
}

TEST_P(SubdomainAssembly, JacobianSumsToTheWholeMesh) {
  const double cj = 2.5;
  const SparsityPattern& pattern = whole_->pattern();
  std::vector<double> values(static_cast<std::size_t>(pattern.nnz())), rates = values;
  whole_->jacobian(kTime, y_.data(), ydot_.data(), cj, values.data(), rates.data());
  std::map<std::pair<Index, Index>, std::pair<double, double>> sum;  // partitioned (row, col)
  for (std::size_t r = 0; r < problems_.size(); ++r) {
    BiphasicModel& local = *problems_[r];
    std::vector<double> lv(static_cast<std::size_t>(local.pattern().nnz())), lr = lv;
    local.jacobian(kTime, part_y_[r].data(), part_ydot_[r].data(), cj, lv.data(), lr.data());
    // Every contributed entry (i, j) of the part's pattern, added at its whole-system place.
    const SubdomainDofs& dofs = dofs_[r];
    const SparsityPattern& lp = local.pattern();
    for (Index j = 0; j < lp.size(); ++j)
      for (Index q = lp.colptr()[static_cast<std::size_t>(j)];
           q < lp.colptr()[static_cast<std::size_t>(j) + 1]; ++q) {
        const Index i = lp.rowind()[static_cast<std::size_t>(q)];
        if (!dofs.contributes(i, j)) continue;
        auto& s = sum[{dofs.global(i), dofs.global(j)}];
        s.first += lv[static_cast<std::size_t>(q)];
        s.second += lr[static_cast<std::size_t>(q)];
      }
  }
  const double scale = max_abs(values), scale_rate = max_abs(rates);
  std::set<std::pair<Index, Index>> seen;
  for (Index j = 0; j < pattern.size(); ++j)
    for (Index k = pattern.colptr()[static_cast<std::size_t>(j)];
         k < pattern.colptr()[static_cast<std::size_t>(j) + 1]; ++k) {
      const Index i = pattern.rowind()[static_cast<std::size_t>(k)];
      const std::pair<Index, Index> key{map_[static_cast<std::size_t>(i)],
                                        map_[static_cast<std::size_t>(j)]};
      const auto it = sum.find(key);
      const double v = it == sum.end() ? 0.0 : it->second.first;
      const double w = it == sum.end() ? 0.0 : it->second.second;
      ASSERT_NEAR(v, values[static_cast<std::size_t>(k)], 1e-12 * scale) << i << ", " << j;
      ASSERT_NEAR(w, rates[static_cast<std::size_t>(k)], 1e-12 * scale_rate) << i << ", " << j;
      seen.insert(key);
    }
  // Entries outside the whole mesh's pattern are zero.
  for (const auto& [key, v] : sum)
    if (!seen.count(key)) {
      EXPECT_EQ(v.first, 0.0) << key.first << ", " << key.second;
    }
}

TEST_P(SubdomainAssembly, ReactionsFluidRatesAndVolumeChangeSumToTheWholeMesh) {
  const std::vector<std::string>& names = reaction_names_;
  const auto reactions = whole_->reactions(names, kTime, y_.data(), ydot_.data());
  const FluidRates rates = whole_->fluid_rates(kTime, y_.data(), ydot_.data());
  const double volume = whole_->volume_change(y_.data());
  std::vector<std::array<double, 3>> reaction_sum(reactions.size(), {0.0, 0.0, 0.0});
  FluidRates rate_sum;
  double volume_sum = 0.0, gls_time = 0.0;
  for (std::size_t r = 0; r < problems_.size(); ++r) {
    BiphasicModel& local = *problems_[r];
    const auto part = local.reactions(names, kTime, part_y_[r].data(), part_ydot_[r].data());
    for (std::size_t b = 0; b < part.size(); ++b)
      for (int c = 0; c < 3; ++c) reaction_sum[b][c] += part[b][c];
    const FluidRates f = local.fluid_rates(kTime, part_y_[r].data(), part_ydot_[r].data());
    rate_sum.drained += f.drained;
    rate_sum.prescribed += f.prescribed;
    rate_sum.source += f.source;
    volume_sum += local.volume_change(part_y_[r].data());
    const double t = local.gls_time_scale();
    gls_time = r == 0 ? t : std::min(gls_time, t);
  }
  for (std::size_t b = 0; b < reactions.size(); ++b)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(reaction_sum[b][c], reactions[b][c], 1e-12 * (1.0 + std::abs(reactions[b][c])))
          << names.size() << " " << b << " " << c;
  EXPECT_NEAR(rate_sum.drained, rates.drained, 1e-14 + 1e-12 * std::abs(rates.drained));
  EXPECT_NEAR(rate_sum.prescribed, rates.prescribed, 1e-14 + 1e-12 * std::abs(rates.prescribed));
  EXPECT_NEAR(rate_sum.source, rates.source, 1e-14 + 1e-12 * std::abs(rates.source));
  EXPECT_NE(rates.prescribed, 0.0);
  EXPECT_NE(rates.source, 0.0);
  EXPECT_NEAR(volume_sum, volume, 1e-14 + 1e-12 * std::abs(volume));
  EXPECT_DOUBLE_EQ(gls_time, whole_->gls_time_scale());
}

TEST_P(SubdomainAssembly, EveryPartSetsItsDirichletUnknownsAsTheWholeMeshDoes) {
  for (std::size_t r = 0; r < problems_.size(); ++r) {
    BiphasicModel& local = *problems_[r];
    std::vector<double> y(static_cast<std::size_t>(local.size()), 7.0), ydot = y;
    local.apply_dirichlet(kTime, y.data(), ydot.data());
    const SubdomainDofs& dofs = dofs_[r];
    EXPECT_EQ(local.solution_scales(), whole_->solution_scales());
    EXPECT_EQ(local.stiffness_scale(), whole_->stiffness_scale());
    EXPECT_EQ(local.conductance_scale(), whole_->conductance_scale());
    for (Index i : dofs.owned()) {
      // The serial unknown of this owned unknown.
      const auto serial = static_cast<std::size_t>(
          std::find(map_.begin(), map_.end(), dofs.global(i)) - map_.begin());
      ASSERT_EQ(local.constrained()[static_cast<std::size_t>(i)], whole_->constrained()[serial]);
      if (whole_->constrained()[serial]) {
        EXPECT_EQ(y[static_cast<std::size_t>(i)], y_[serial]);
        EXPECT_EQ(ydot[static_cast<std::size_t>(i)], ydot_[serial]);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Parts, SubdomainAssembly,
                         ::testing::Combine(::testing::Values(Scene::Tetrahedra, Scene::PlaneStrain,
                                                              Scene::Axisymmetric),
                                            ::testing::Values(1, 2, 3, 4)),
                         [](const ::testing::TestParamInfo<std::tuple<Scene, int>>& param) {
                           return scene_name(std::get<0>(param.param)) + "_" +
                                  std::to_string(std::get<1>(param.param));
                         });

}  // namespace
}  // namespace biphasic
