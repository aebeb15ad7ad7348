// The case-file schema table, and what is generated from it: the Markdown key reference and
// the JSON dump of a resolved Config.
#include "case_schema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include "biphasic/io/case_file.hpp"
#include "biphasic/material/material_laws.hpp"
#include "biphasic/physics/stabilisation/stabilisations.hpp"

namespace biphasic::case_schema {

namespace {

template <class E>
using Names = std::vector<std::pair<std::string, E>>;

const Names<MeshSource>& mesh_source_names() {
  static const Names<MeshSource> names{{"quarter_cylinder", MeshSource::QuarterCylinder},
                                       {"column", MeshSource::Column},
                                       {"sphere_octant", MeshSource::SphereOctant},
                                       {"section", MeshSource::Section},
                                       {"file", MeshSource::File}};
  return names;
}

const Names<ModelKind>& model_names() {
  static const Names<ModelKind> names{{"three_dimensional", ModelKind::ThreeDimensional},
                                      {"axisymmetric", ModelKind::Axisymmetric},
                                      {"plane_strain", ModelKind::PlaneStrain}};
  return names;
}

const Names<BcType>& bc_names() {
  static const Names<BcType> names{
      {"displacement", BcType::Displacement}, {"symmetry", BcType::Symmetry},
      {"pressure", BcType::Pressure},         {"flux", BcType::Flux},
      {"traction", BcType::Traction},         {"normal_traction", BcType::NormalTraction},
      {"rigid_platen", BcType::RigidPlaten}};
  return names;
}

const Names<int>& component_names() {
  static const Names<int> names{{"x", 0}, {"y", 1}, {"z", 2}};
  return names;
}

const Names<ElementLength>& element_length_names() {
  static const Names<ElementLength> names{{"circumradius", ElementLength::Circumradius},
                                          {"shortest_edge", ElementLength::ShortestEdge},
                                          {"longest_edge", ElementLength::LongestEdge},
                                          {"volume_diameter", ElementLength::VolumeDiameter}};
  return names;
}

const Names<GlsQuadrature>& gls_quadrature_names() {
  static const Names<GlsQuadrature> names{{"full", GlsQuadrature::Full},
                                          {"one_point", GlsQuadrature::OnePoint}};
  return names;
}

const Names<Integrator>& integrator_names() {
  static const Names<Integrator> names{
      {"backward_euler", Integrator::BackwardEuler},
      {"bdf", Integrator::Bdf},
      {"adaptive_backward_euler", Integrator::AdaptiveBackwardEuler}};
  return names;
}

const Names<VolumeRate>& volume_rate_names() {
  static const Names<VolumeRate> names{{"incremental", VolumeRate::Incremental},
                                       {"conservative", VolumeRate::Conservative}};
  return names;
}

const Names<LinearSolverType>& linear_solver_names() {
  static const Names<LinearSolverType> names{{"klu", LinearSolverType::Klu},
                                             {"umfpack", LinearSolverType::Umfpack},
                                             {"mumps", LinearSolverType::Mumps},
                                             {"iterative", LinearSolverType::Iterative},
                                             {"superlu_dist", LinearSolverType::SuperluDist}};
  return names;
}

const Names<Ordering>& ordering_names() {
  static const Names<Ordering> names{
      {"amd", Ordering::Amd}, {"colamd", Ordering::Colamd}, {"metis", Ordering::Metis}};
  return names;
}

const Names<FieldQuantity>& field_quantity_names() {
  static const Names<FieldQuantity> names{{"displacement", FieldQuantity::Displacement},
                                          {"pressure", FieldQuantity::Pressure},
                                          {"stress", FieldQuantity::Stress},
                                          {"effective_stress", FieldQuantity::EffectiveStress},
                                          {"J", FieldQuantity::J},
                                          {"flux", FieldQuantity::Flux},
                                          {"permeability", FieldQuantity::Permeability}};
  return names;
}

const Names<FactorPrecision>& precision_names() {
  static const Names<FactorPrecision> names{{"double", FactorPrecision::Double},
                                            {"mixed", FactorPrecision::Mixed}};
  return names;
}

template <class E>
std::vector<std::string> names_of(const Names<E>& names) {
  std::vector<std::string> out;
  for (const auto& entry : names) out.push_back(entry.first);
  return out;
}

template <class E>
std::string name_of(const Names<E>& names, E value) {
  for (const auto& entry : names) {
    if (entry.second == value) return entry.first;
  }
  throw std::logic_error("case schema: enum value without a name");
}

template <class E>
E value_of(const Names<E>& names, const std::string& name) {
  for (const auto& entry : names) {
    if (entry.first == name) return entry.second;
  }
  throw std::logic_error("case schema: unknown choice '" + name + "'");
}

Range above(double a) { return Range{a, std::nullopt, true, false}; }
Range at_least(double a) { return Range{a, std::nullopt, false, false}; }
Range strictly_between(double a, double b) { return Range{a, b, true, true}; }
Range from_to(double a, double b) { return Range{a, b, false, false}; }

template <class Target>
Key<Target> make_key(std::string path, Kind kind, std::string unit, std::string help) {
  Key<Target> key;
  key.path = std::move(path);
  key.kind = kind;
  key.unit = std::move(unit);
  key.help = std::move(help);
  return key;
}

// The builders below take `access`, a generic lambda returning a reference to the field, so
// one accessor serves both storing (non-const) and fetching (const).

template <class Target, class Access>
Key<Target> number_key(std::string path, Range range, std::string unit, std::string help,
                       Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Number, std::move(unit), std::move(help));
  key.range = range;
  key.store = [access](Target& t, const Value& v) { access(t) = std::get<double>(v); };
  key.fetch = [access](const Target& t) -> Value { return double{access(t)}; };
  return key;
}

template <class Target, class Access>
Key<Target> integer_key(std::string path, Range range, std::vector<std::int64_t> allowed,
                        std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Integer, "", std::move(help));
  key.range = range;
  key.allowed = std::move(allowed);
  key.store = [access](Target& t, const Value& v) {
    access(t) = static_cast<int>(std::get<std::int64_t>(v));
  };
  key.fetch = [access](const Target& t) -> Value { return std::int64_t{access(t)}; };
  return key;
}

template <class Target, class Access>
Key<Target> bool_key(std::string path, std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Boolean, "", std::move(help));
  key.store = [access](Target& t, const Value& v) { access(t) = std::get<bool>(v); };
  key.fetch = [access](const Target& t) -> Value { return bool{access(t)}; };
  return key;
}

template <class Target, class Access>
Key<Target> string_key(std::string path, std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::String, "", std::move(help));
  key.store = [access](Target& t, const Value& v) { access(t) = std::get<std::string>(v); };
  key.fetch = [access](const Target& t) -> Value { return std::string{access(t)}; };
  return key;
}

template <class Target, class E, class Access>
Key<Target> choice_key(std::string path, const Names<E>& names, std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Choice, "", std::move(help));
  key.choices = names_of(names);
  key.store = [access, &names](Target& t, const Value& v) {
    access(t) = value_of(names, std::get<std::string>(v));
  };
  key.fetch = [access, &names](const Target& t) -> Value { return name_of(names, access(t)); };
  return key;
}

template <class Target, class Access>
Key<Target> vector_key(std::string path, std::string unit, std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Vector3, std::move(unit), std::move(help));
  key.store = [access](Target& t, const Value& v) {
    access(t) = std::get<std::array<double, 3>>(v);
  };
  key.fetch = [access](const Target& t) -> Value { return std::array<double, 3>{access(t)}; };
  return key;
}

template <class Target, class Access>
Key<Target> string_list_key(std::string path, std::vector<std::string> choices, std::string help,
                            Access access) {
  auto key = make_key<Target>(std::move(path), Kind::StringList, "", std::move(help));
  key.choices = std::move(choices);
  key.store = [access](Target& t, const Value& v) {
    access(t) = std::get<std::vector<std::string>>(v);
  };
  key.fetch = [access](const Target& t) -> Value { return std::vector<std::string>{access(t)}; };
  return key;
}

template <class Target, class Access>
Key<Target> number_list_key(std::string path, Range range, std::string unit, std::string help,
                            Access access) {
  auto key = make_key<Target>(std::move(path), Kind::NumberList, std::move(unit), std::move(help));
  key.range = range;
  key.store = [access](Target& t, const Value& v) { access(t) = std::get<std::vector<double>>(v); };
  key.fetch = [access](const Target& t) -> Value { return std::vector<double>{access(t)}; };
  return key;
}

/// A Selection key: `true` stores `defaults`, `false` nothing, an array the named values (in
/// the order of `names`, whatever the order given). Reported back the same way: `true` for
/// the defaults, `false` for none, else the names.
template <class Target, class E, class Access>
Key<Target> selection_key(std::string path, const Names<E>& names, std::vector<E> defaults,
                          std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Selection, "", std::move(help));
  key.choices = names_of(names);
  key.store = [access, &names, defaults](Target& t, const Value& v) {
    std::vector<E>& chosen = access(t);
    if (const bool* all = std::get_if<bool>(&v)) {
      chosen = *all ? defaults : std::vector<E>{};
      return;
    }
    const auto& given = std::get<std::vector<std::string>>(v);
    chosen.clear();
    for (const auto& entry : names) {
      if (std::find(given.begin(), given.end(), entry.first) != given.end())
        chosen.push_back(entry.second);
    }
  };
  key.fetch = [access, &names, defaults](const Target& t) -> Value {
    const std::vector<E>& chosen = access(t);
    if (chosen == defaults) return true;
    if (chosen.empty()) return false;
    std::vector<std::string> out;
    for (E value : chosen) out.push_back(name_of(names, value));
    return out;
  };
  return key;
}

template <class Target, class Access>
Key<Target> expression_key(std::string path, std::string unit, std::string help, Access access) {
  auto key = make_key<Target>(std::move(path), Kind::Expression, std::move(unit), std::move(help));
  key.store = [access](Target& t, const Value& v) {
    access(t) = Expression::parse(std::get<std::string>(v));
  };
  key.fetch = [access](const Target& t) -> Value { return std::string{access(t).text()}; };
  return key;
}

/// Per-type rule: `required` types must give the key, `forbidden` ones must not, others may.
std::array<Need, kBcTypeCount> needs(std::initializer_list<BcType> required,
                                     std::initializer_list<BcType> forbidden) {
  std::array<Need, kBcTypeCount> out{};
  out.fill(Need::Optional);
  for (BcType t : required) out[static_cast<std::size_t>(t)] = Need::Required;
  for (BcType t : forbidden) out[static_cast<std::size_t>(t)] = Need::Forbidden;
  return out;
}

Range range_of(const ParameterBounds& b) { return Range{b.min, b.max, b.min_open, b.max_open}; }

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (const auto& part : parts) out += (out.empty() ? "" : separator) + part;
  return out;
}

/// The keys of [material], derived from the registered laws (material_laws.hpp): per family
/// the choice key, then each parameter of its laws once, its help naming the laws that read it
/// unless every law of the family does.
std::vector<Key<Config>> material_keys() {
  using C = Config;
  std::vector<Key<C>> keys;
  std::vector<std::string> emitted;
  for (const LawFamily& family : material_law_families()) {
    std::vector<std::string> names, described;
    for (const LawDescription& law : family.laws) {
      names.push_back(law.name);
      std::vector<std::string> keys_of_law;
      for (const LawParameter& p : law.parameters) keys_of_law.push_back("material." + p.name);
      described.push_back(law.name + " (" + law.summary + "; " + joined(keys_of_law, ", ") + ")");
    }
    auto choice = make_key<C>("material." + family.key, Kind::Choice, "",
                              family.what + ": " + joined(described, "; ") +
                                  ". A parameter of a law not chosen is an error.");
    choice.choices = names;
    const auto chosen = family.chosen;
    choice.store = [chosen](C& c, const Value& v) {
      c.material.*chosen = std::get<std::string>(v);
    };
    choice.fetch = [chosen](const C& c) -> Value { return c.material.*chosen; };
    keys.push_back(choice);

    for (const LawDescription& law : family.laws) {
      for (const LawParameter& p : law.parameters) {
        if (std::find(emitted.begin(), emitted.end(), p.name) != emitted.end()) continue;
        emitted.push_back(p.name);
        std::vector<std::string> readers;
        for (const LawDescription& other : family.laws) {
          if (other.reads(p.name)) readers.push_back(other.name);
        }
        std::string help = p.help;
        if (readers.size() < family.laws.size()) {
          help += " Read by material." + family.key + " = " + joined(readers, ", ") + ".";
        }
        const std::string name = p.name;
        auto key = make_key<C>("material." + name, Kind::Number, p.unit, help);
        key.range = range_of(p.bounds);
        key.store = [name](C& c, const Value& v) { c.material.set(name, std::get<double>(v)); };
        key.fetch = [name](const C& c) -> Value { return c.material.get(name); };
        keys.push_back(key);
      }
    }
  }
  return keys;
}

std::vector<Key<Config>> build_global_keys() {
  using C = Config;
  std::vector<Key<C>> keys;

  auto version =
      make_key<C>("format_version", Kind::Integer, "", "Case-file format version; must be 1.");
  version.allowed = {1};
  version.required = true;
  version.fetch = [](const C&) -> Value { return std::int64_t{1}; };
  keys.push_back(version);
  keys.push_back(string_key<C>(
      "title", "Free-text title of the run, copied to the outputs.",
      [](auto& c) -> auto& { return c.title; }));

  keys.push_back(choice_key<C>(
      "model", model_names(),
      "Kinematics: the three-dimensional body on tetrahedra, or a two-dimensional section on "
      "6-node triangles (mesh.source = \"section\" or a .msh file of triangles): axisymmetric "
      "(x = r, y = z; forces over the full circle) or plane strain (u_z = 0; forces per mm of "
      "thickness). Components and points are then (x, y) with z = 0.",
      [](auto& c) -> auto& { return c.model; }));
  keys.push_back(choice_key<C>(
      "mesh.source", mesh_source_names(),
      "Where the mesh comes from: a generated quarter cylinder (keys mesh.radius ... "
      "mesh.grading_distance), column ([mesh.column]), sphere octant ([mesh.sphere_octant]) or, "
      "for a two-dimensional model, rectangular section ([mesh.section]); or a gmsh file "
      "(mesh.file). Keys of another generated source are an error.",
      [](auto& c) -> auto& { return c.mesh.source; }));
  keys.push_back(string_key<C>(
      "mesh.file",
      "gmsh .msh file (format 2.2 or 4.1): 4- or 10-node tetrahedra with named physical "
      "surfaces, or, for a two-dimensional model, 3- or 6-node triangles in z = 0 with named "
      "physical curves. "
      "Required when mesh.source = \"file\", and must then exist; a relative path is relative "
      "to the case file's folder.",
      [](auto& c) -> auto& { return c.mesh.file; }));
  keys.push_back(number_key<C>(
      "mesh.radius", above(0), "mm",
      "Radius of the quarter cylinder (mesh.source = \"quarter_cylinder\").",
      [](auto& c) -> auto& { return c.mesh.cylinder.radius; }));
  keys.push_back(number_key<C>(
      "mesh.height", above(0), "mm",
      "Height of the quarter cylinder (mesh.source = \"quarter_cylinder\").",
      [](auto& c) -> auto& { return c.mesh.cylinder.height; }));
  keys.push_back(number_key<C>(
      "mesh.lc", above(0), "mm",
      "Characteristic element length of the quarter cylinder (mesh.source = \"quarter_cylinder\").",
      [](auto& c) -> auto& { return c.mesh.cylinder.lc; }));
  keys.push_back(string_list_key<C>(
      "mesh.grading_faces", {"bottom", "top", "lateral", "symmetry_x", "symmetry_y"},
      "Faces of the quarter cylinder near which elements shrink to lc / grading_ratio "
      "(empty = uniform mesh).",
      [](auto& c) -> auto& { return c.mesh.cylinder.grading_faces; }));
  keys.push_back(number_key<C>(
      "mesh.grading_ratio", at_least(1), "",
      "Element size on the graded faces is lc divided by this ratio (1 = uniform).",
      [](auto& c) -> auto& { return c.mesh.cylinder.grading_ratio; }));
  keys.push_back(number_key<C>(
      "mesh.grading_distance", above(0), "mm",
      "Distance from the graded faces over which the element size grows back to lc.",
      [](auto& c) -> auto& { return c.mesh.cylinder.grading_distance; }));
  keys.push_back(integer_key<C>(
      "mesh.layers", at_least(0), {},
      "> 0: a swept quarter cylinder: the bottom quarter disc triangulated at lc and extruded "
      "along z in this many layers of tetrahedra, thin layers resolving the boundary layers "
      "at the drained faces cheaply (0 = unstructured tetrahedra).",
      [](auto& c) -> auto& { return c.mesh.cylinder.layers; }));
  keys.push_back(string_list_key<C>(
      "mesh.layer_grading_faces", {"bottom", "top"},
      "Swept mesh: faces the layer thicknesses shrink toward, geometrically (empty = uniform "
      "layers).",
      [](auto& c) -> auto& { return c.mesh.cylinder.layer_grading_faces; }));
  keys.push_back(number_key<C>(
      "mesh.layer_grading_ratio", from_to(1, 1e6), "",
      "Swept mesh: thickest over thinnest layer (1 = uniform).",
      [](auto& c) -> auto& { return c.mesh.cylinder.layer_grading_ratio; }));
  keys.push_back(string_key<C>(
      "mesh.write_msh",
      "If not empty, write the mesh generated by gmsh (quarter_cylinder, sphere_octant) to this "
      ".msh file inside the output folder: a relative path ending in .msh, without '..'.",
      [](auto& c) -> auto& { return c.mesh.cylinder.write_msh; }));

  keys.push_back(bool_key<C>(
      "mesh.ignore_memory_estimate",
      "Run even if the estimate of the memory the mesh needs (from its parameters, before "
      "meshing) exceeds the memory available (MemAvailable); `check` prints the estimate.",
      [](auto& c) -> auto& { return c.mesh.ignore_memory_estimate; }));

  keys.push_back(number_key<C>(
      "mesh.column.width", above(0), "mm", "Extent of the column in x (faces x0, x1).",
      [](auto& c) -> auto& { return c.mesh.column.width; }));
  keys.push_back(number_key<C>(
      "mesh.column.depth", above(0), "mm", "Extent of the column in y (faces y0, y1).",
      [](auto& c) -> auto& { return c.mesh.column.depth; }));
  keys.push_back(number_key<C>(
      "mesh.column.height", above(0), "mm", "Extent of the column in z (faces bottom, top).",
      [](auto& c) -> auto& { return c.mesh.column.height; }));
  keys.push_back(integer_key<C>(
      "mesh.column.nx", at_least(1), {},
      "Cells in x; each hexahedral cell is split into six tetrahedra.",
      [](auto& c) -> auto& { return c.mesh.column.nx; }));
  keys.push_back(integer_key<C>(
      "mesh.column.ny", at_least(1), {}, "Cells in y.",
      [](auto& c) -> auto& { return c.mesh.column.ny; }));
  keys.push_back(integer_key<C>(
      "mesh.column.nz", at_least(1), {},
      "Layers in z (at least 2 when graded toward one face, 3 toward both).",
      [](auto& c) -> auto& { return c.mesh.column.nz; }));
  keys.push_back(string_list_key<C>(
      "mesh.column.grading_faces", {"bottom", "top"},
      "Faces the layers are graded toward: their thicknesses grow geometrically away from "
      "these faces (empty = uniform layers).",
      [](auto& c) -> auto& { return c.mesh.column.grading_faces; }));
  keys.push_back(number_key<C>(
      "mesh.column.grading_ratio", from_to(1, 1e6), "",
      "Thickest over thinnest layer (1 = uniform).",
      [](auto& c) -> auto& { return c.mesh.column.grading_ratio; }));
  keys.push_back(string_list_key<C>(
      "mesh.column.region_names", {},
      "Material regions stacked from the bottom, one name each (a [[region]] entry gives each "
      "its material); empty = no regions. With mesh.column.region_tops.",
      [](auto& c) -> auto& { return c.mesh.column.region_names; }));
  keys.push_back(number_list_key<C>(
      "mesh.column.region_tops", above(0), "mm",
      "Top z of each region of mesh.column.region_names, increasing, each a layer interface, "
      "the last = mesh.column.height.",
      [](auto& c) -> auto& { return c.mesh.column.region_tops; }));

  keys.push_back(number_key<C>(
      "mesh.sphere_octant.radius", above(0), "mm",
      "Radius of the ball octant x, y, z >= 0 (boundaries surface, symmetry_x, symmetry_y, "
      "symmetry_z).",
      [](auto& c) -> auto& { return c.mesh.sphere_octant.radius; }));
  keys.push_back(number_key<C>(
      "mesh.sphere_octant.lc", above(0), "mm", "Characteristic element length.",
      [](auto& c) -> auto& { return c.mesh.sphere_octant.lc; }));
  keys.push_back(number_key<C>(
      "mesh.sphere_octant.grading_ratio", at_least(1), "",
      "Element size on the spherical surface is lc divided by this ratio (1 = uniform).",
      [](auto& c) -> auto& { return c.mesh.sphere_octant.grading_ratio; }));
  keys.push_back(number_key<C>(
      "mesh.sphere_octant.grading_distance", above(0), "mm",
      "Distance from the surface over which the element size grows back to lc.",
      [](auto& c) -> auto& { return c.mesh.sphere_octant.grading_distance; }));

  keys.push_back(number_key<C>(
      "mesh.section.width", above(0), "mm",
      "Extent in x (the radius of an axisymmetric body): curves axis (x = 0) and lateral.",
      [](auto& c) -> auto& { return c.mesh.section.width; }));
  keys.push_back(number_key<C>(
      "mesh.section.height", above(0), "mm",
      "Extent in y (= z of an axisymmetric body): "
      "curves bottom (y = 0) and top.",
      [](auto& c) -> auto& { return c.mesh.section.height; }));
  keys.push_back(integer_key<C>(
      "mesh.section.nr", at_least(1), {}, "Cells across the width.",
      [](auto& c) -> auto& { return c.mesh.section.nr; }));
  keys.push_back(integer_key<C>(
      "mesh.section.nz", at_least(1), {}, "Cells over the height.",
      [](auto& c) -> auto& { return c.mesh.section.nz; }));
  keys.push_back(string_list_key<C>(
      "mesh.section.grading_curves", {"axis", "lateral", "bottom", "top"},
      "Curves the cells shrink toward, geometrically (empty = uniform).",
      [](auto& c) -> auto& { return c.mesh.section.grading_curves; }));
  keys.push_back(number_key<C>(
      "mesh.section.grading_ratio", from_to(1, 1e6), "",
      "Largest over smallest cell size in each graded direction (1 = uniform).",
      [](auto& c) -> auto& { return c.mesh.section.grading_ratio; }));

  for (auto& key : material_keys()) keys.push_back(std::move(key));

  auto curve = make_key<C>("curves.<name>", Kind::Curve, "s, -",
                           "Named piecewise-linear load curve [[t, value], ...]: at least one "
                           "point, times strictly increasing; constant before the first and "
                           "after the last point. Referenced by boundary[i].curve.");
  keys.push_back(curve);

  const std::array<std::string, 3> axes{"x", "y", "z"};
  for (std::size_t i = 0; i < 3; ++i) {
    keys.push_back(expression_key<C>(
        "body_force." + axes[i], "N/mm^3",
        "Component " + axes[i] +
            " of the body force b per unit reference volume, a formula of "
            "x, y, z (reference position, mm) and t (s); enters the momentum balance as "
            "-Div P = b.",
        [i](auto& c) -> auto& { return c.loads.body_force[i]; }));
  }
  keys.push_back(expression_key<C>(
      "fluid_source.value", "1/s",
      "Volumetric fluid source s per unit reference volume, a formula of x, y, z and t; the "
      "mass balance reads dJ/dt + Div W = s (W the reference seepage), so s > 0 injects fluid.",
      [](auto& c) -> auto& { return c.loads.fluid_source; }));

  {
    // The choices and their summaries come from the registered stabilisations.
    std::vector<std::string> names, described;
    for (const StabilisationDescription& d : stabilisation_descriptions()) {
      names.push_back(d.name);
      described.push_back(d.name + " (" + d.summary + ")");
    }
    auto type = make_key<C>("stabilisation.type", Kind::Choice, "",
                            "Pressure stabilisation: " + joined(described, "; ") + ".");
    type.choices = names;
    type.store = [](C& c, const Value& v) { c.stabilisation.type = std::get<std::string>(v); };
    type.fetch = [](const C& c) -> Value { return c.stabilisation.type; };
    keys.push_back(type);
  }
  keys.push_back(choice_key<C>(
      "stabilisation.length", element_length_names(),
      "Element length h in the GLS parameter c_e = h^2 / (4 k).",
      [](auto& c) -> auto& { return c.stabilisation.length; }));
  keys.push_back(number_key<C>(
      "stabilisation.scale", above(0), "",
      "Multiplier of the stabilisation's coefficient, c_e or beta, through h^2 (1 = standard).",
      [](auto& c) -> auto& { return c.stabilisation.scale; }));
  keys.push_back(choice_key<C>(
      "stabilisation.gls_quadrature", gls_quadrature_names(),
      "Quadrature of the GLS term (gls, gls_minimal): full (quadrature.points, the paper's) or "
      "one_point (reduced: the centroid alone, every other term keeping the full rule; "
      "tetrahedra only).",
      [](auto& c) -> auto& { return c.stabilisation.gls_quadrature; }));
  keys.push_back(number_key<C>(
      "stabilisation.threshold", above(0), "",
      "r* of gls_minimal and flux_perturbation_minimal: elements with k H_A time_step / h^2 >= "
      "r* are left unstabilised, the others get the least coefficient that makes the first "
      "backward-Euler step monotone (0.25: the published coefficients as k dt/h^2 -> 0).",
      [](auto& c) -> auto& { return c.stabilisation.threshold; }));
  keys.push_back(number_key<C>(
      "stabilisation.time_step", at_least(0), "s",
      "The step dt* that gls_minimal and flux_perturbation_minimal are sized for, frozen for "
      "the whole run so that the residual is one function F(t, y, y') under BDF too; 0 (the "
      "default) = time.dt.",
      [](auto& c) -> auto& { return c.stabilisation.time_step; }));

  keys.push_back(integer_key<C>(
      "quadrature.points", Range{}, {1, 4, 5, 8, 27, 64, 125}, "Quadrature points per tetrahedron.",
      [](auto& c) -> auto& { return c.quadrature_points; }));

  keys.push_back(choice_key<C>(
      "time.integrator", integrator_names(),
      "Time integrator: backward_euler (fixed time.dt, the paper's), bdf (SUNDIALS IDA, "
      "variable order and step; outputs every time.dt) or adaptive_backward_euler (IDA held at "
      "order 1: error-controlled backward Euler with the time.bdf settings).",
      [](auto& c) -> auto& { return c.time.integrator; }));
  keys.push_back(number_key<C>(
      "time.t_end", above(0), "s", "End time of the run (starts at 0).",
      [](auto& c) -> auto& { return c.time.t_end; }));
  keys.push_back(number_key<C>(
      "time.dt", above(0), "s",
      "Backward-Euler time step, and the output interval of bdf; must be <= time.t_end, and "
      "time.t_end / time.dt at most 1e7 steps.",
      [](auto& c) -> auto& { return c.time.dt; }));
  keys.push_back(choice_key<C>(
      "time.volume_rate", volume_rate_names(),
      "Backward Euler's dJ/dt in the mass rows and the GLS term: incremental, J F^-T : "
      "Grad(u - u_n) / dt (the paper's), or conservative, (J - J_n) / dt (exact discrete fluid "
      "volume balance). backward_euler only.",
      [](auto& c) -> auto& { return c.time.volume_rate; }));

  keys.push_back(integer_key<C>(
      "time.newton.max_iterations", from_to(1, 1000), {},
      "Maximum Newton iterations per time step.",
      [](auto& c) -> auto& { return c.time.newton.max_iterations; }));
  keys.push_back(number_key<C>(
      "time.newton.rtol_displacement", strictly_between(0, 1), "",
      "Relative tolerance on the momentum residual (max norm, relative to the predictor's).",
      [](auto& c) -> auto& { return c.time.newton.rtol_displacement; }));
  keys.push_back(number_key<C>(
      "time.newton.rtol_pressure", strictly_between(0, 1), "",
      "Relative tolerance on the mass residual (max norm, relative to the predictor's).",
      [](auto& c) -> auto& { return c.time.newton.rtol_pressure; }));
  keys.push_back(number_key<C>(
      "time.newton.atol_displacement", at_least(0), "N",
      "Absolute tolerance on the momentum residual (max norm); refused above 0.1 % of the force "
      "scale H_A h u the loads imply (h the mean element size, u the displacement scale).",
      [](auto& c) -> auto& { return c.time.newton.atol_displacement; }));
  keys.push_back(number_key<C>(
      "time.newton.atol_pressure", at_least(0), "mm^3/s",
      "Absolute tolerance on the mass residual (max norm); refused above 0.1 % of the "
      "volume-rate scale k h p the loads imply (p the pressure scale).",
      [](auto& c) -> auto& { return c.time.newton.atol_pressure; }));
  keys.push_back(integer_key<C>(
      "time.newton.max_setup_calls", at_least(1), {},
      "Newton iterations between Jacobian refreshes (1 = full Newton).",
      [](auto& c) -> auto& { return c.time.newton.max_setup_calls; }));
  keys.push_back(bool_key<C>(
      "time.newton.reuse_across_steps",
      "Keep the Jacobian factorisation from the previous time step.",
      [](auto& c) -> auto& { return c.time.newton.reuse_across_steps; }));
  keys.push_back(integer_key<C>(
      "time.newton.max_cutbacks", from_to(0, 30), {},
      "Backward Euler: after a failed Newton solve (no convergence, inverted element), halve the "
      "step and retry from the last converged state, down to time.dt / 2^max_cutbacks; the step "
      "doubles again after 2 successful sub-steps and outputs stay at t0 + k dt (0 = a failure "
      "stops the run).",
      [](auto& c) -> auto& { return c.time.newton.max_cutbacks; }));

  keys.push_back(number_key<C>(
      "time.bdf.rtol", strictly_between(0, 1), "", "Relative tolerance of IDA's local error test.",
      [](auto& c) -> auto& { return c.time.bdf.rtol; }));
  keys.push_back(number_key<C>(
      "time.bdf.atol_displacement", at_least(0), "mm",
      "Absolute tolerance on displacements; 0 = rtol times the largest prescribed displacement "
      "(or the strain a traction imposes).",
      [](auto& c) -> auto& { return c.time.bdf.atol_displacement; }));
  keys.push_back(number_key<C>(
      "time.bdf.atol_pressure", at_least(0), "MPa",
      "Absolute tolerance on pressures; 0 = rtol times H_A times the applied strain (or the "
      "prescribed pressure or traction).",
      [](auto& c) -> auto& { return c.time.bdf.atol_pressure; }));
  keys.push_back(integer_key<C>(
      "time.bdf.max_order", from_to(1, 5), {}, "Maximum BDF order.",
      [](auto& c) -> auto& { return c.time.bdf.max_order; }));
  keys.push_back(number_key<C>(
      "time.bdf.initial_step", at_least(0), "s",
      "First step; 0 = 1 % of the first output interval (or of the time to the first load-curve "
      "kink).",
      [](auto& c) -> auto& { return c.time.bdf.initial_step; }));
  keys.push_back(number_key<C>(
      "time.bdf.max_step", at_least(0), "s", "Largest step; 0 = unlimited.",
      [](auto& c) -> auto& { return c.time.bdf.max_step; }));
  keys.push_back(integer_key<C>(
      "time.bdf.max_steps", from_to(1, 100000000), {},
      "Internal steps allowed between two outputs; one more stops the run with an error.",
      [](auto& c) -> auto& { return c.time.bdf.max_steps; }));
  keys.push_back(number_key<C>(
      "time.bdf.delta_cj", strictly_between(0, 1), "",
      "Relative change of c_j = alpha/h that forces a new factorisation (IDASetDeltaCjLSetup).",
      [](auto& c) -> auto& { return c.time.bdf.delta_cj; }));
  keys.push_back(number_key<C>(
      "time.bdf.max_growth", above(1), "",
      "Largest ratio of one step to the previous (IDASetEtaMax).",
      [](auto& c) -> auto& { return c.time.bdf.max_growth; }));
  keys.push_back(bool_key<C>(
      "time.bdf.shift_correction",
      "Solve each Newton correction with the current c_j on the last factorisation (GMRES "
      "preconditioned by it) rather than IDA's scaled stale-c_j correction.",
      [](auto& c) -> auto& { return c.time.bdf.shift_correction; }));
  keys.push_back(bool_key<C>(
      "time.bdf.restart_from_last_step",
      "After a load-curve kink, restart from the last accepted step (else from initial_step).",
      [](auto& c) -> auto& { return c.time.bdf.restart_from_last_step; }));
  keys.push_back(bool_key<C>(
      "time.bdf.stop_at_outputs",
      "End an internal step on every output time (outputs are step values, not interpolated; "
      "with GLS the reactions depend on the rate).",
      [](auto& c) -> auto& { return c.time.bdf.stop_at_outputs; }));
  keys.push_back(bool_key<C>(
      "time.bdf.step_log", "Write steps.csv with t, h and order of every internal step.",
      [](auto& c) -> auto& { return c.time.bdf.step_log; }));

  keys.push_back(choice_key<C>(
      "linear_solver.type", linear_solver_names(),
      "Linear solver: mumps and umfpack (multifrontal, BLAS-3; fast with OpenBLAS), klu (no "
      "BLAS; suits small problems), iterative (FGMRES with BoomerAMG on the displacement "
      "block and a pressure Schur-complement approximation; for meshes too large to factorise), or "
      "superlu_dist (SuperLU_DIST, under mpirun with several processes only).",
      [](auto& c) -> auto& { return c.linear_solver.type; }));
  keys.push_back(choice_key<C>(
      "linear_solver.ordering", ordering_names(),
      "Fill-reducing ordering of the sparse factorisation.",
      [](auto& c) -> auto& { return c.linear_solver.ordering; }));
  keys.push_back(choice_key<C>(
      "linear_solver.precision", precision_names(),
      "MUMPS' factors: `mixed` factorises in single precision and refines each solve in double "
      "precision to a componentwise backward error of 1e-6 and a relative residual of 1e-4 "
      "(falling back to `double` if that fails); `double` factorises in double precision.",
      [](auto& c) -> auto& { return c.linear_solver.precision; }));
  keys.push_back(bool_key<C>(
      "linear_solver.out_of_core",
      "MUMPS only: write the factors to files as they are computed and read them back at each "
      "solve (out-of-core), so that memory holds only the fronts being worked on: about a third "
      "of the in-memory peak on the paper's mesh 4 (docs/performance.md, *Out-of-core factors*).",
      [](auto& c) -> auto& { return c.linear_solver.out_of_core; }));
  keys.push_back(string_key<C>(
      "linear_solver.out_of_core_directory",
      "Folder for the out-of-core factors (an existing, writable one; a relative path is "
      "relative to the case file). Default: $TMPDIR, else /tmp. On a cluster, a disk local to "
      "the node.",
      [](auto& c) -> auto& { return c.linear_solver.out_of_core_directory; }));
  keys.push_back(number_key<C>(
      "linear_solver.krylov.rtol", strictly_between(0, 1), "",
      "Iterative solver: relative residual reduction per solve (fields scaled alike).",
      [](auto& c) -> auto& { return c.linear_solver.krylov.rtol; }));
  keys.push_back(integer_key<C>(
      "linear_solver.krylov.max_iterations", from_to(1, 100000), {},
      "Iterative solver: FGMRES iterations allowed per solve, restarts included (exactly, also "
      "when below or not a multiple of restart).",
      [](auto& c) -> auto& { return c.linear_solver.krylov.max_iterations; }));
  keys.push_back(integer_key<C>(
      "linear_solver.krylov.restart", from_to(5, 1000), {},
      "Iterative solver: Krylov vectors kept before FGMRES restarts.",
      [](auto& c) -> auto& { return c.linear_solver.krylov.restart; }));
  keys.push_back(number_key<C>(
      "linear_solver.krylov.amg_threshold", strictly_between(0, 1), "",
      "Iterative solver: BoomerAMG strong-connection threshold on the displacement block.",
      [](auto& c) -> auto& { return c.linear_solver.krylov.amg_threshold; }));
  keys.push_back(integer_key<C>(
      "linear_solver.krylov.amg_cycles", from_to(1, 10), {},
      "Iterative solver: AMG V-cycles per preconditioner application.",
      [](auto& c) -> auto& { return c.linear_solver.krylov.amg_cycles; }));
  keys.push_back(number_key<C>(
      "linear_solver.krylov.block_rtol", at_least(0), "",
      "Iterative solver: if > 0, solve the displacement block by inner GMRES + AMG to this "
      "relative residual in each preconditioner application; 0 = V-cycles only.",
      [](auto& c) -> auto& { return c.linear_solver.krylov.block_rtol; }));

  keys.push_back(vector_key<C>(
      "output.line_start", "mm", "Start point of the probe line.",
      [](auto& c) -> auto& { return c.output.line_start; }));
  keys.push_back(vector_key<C>(
      "output.line_end", "mm", "End point of the probe line; must differ from line_start.",
      [](auto& c) -> auto& { return c.output.line_end; }));
  keys.push_back(integer_key<C>(
      "output.line_points", from_to(0, static_cast<double>(kMaxProbePoints)), {},
      "Samples of the probe line: 0 = the mesh nodes on the line when it runs along the mesh "
      "from start to end (element edges or node to node through elements), else 101 evenly "
      "spaced points; n >= 2 = n evenly spaced points, the fields interpolated by the element "
      "shape functions (docs/probes.md).",
      [](auto& c) -> auto& { return c.output.line_points; }));
  keys.push_back(integer_key<C>(
      "output.every", at_least(1), {},
      "Write outputs every n steps (the last step is always written).",
      [](auto& c) -> auto& { return c.output.every; }));
  keys.push_back(selection_key<C>(
      "output.fields", field_quantity_names(), default_field_quantities(),
      "The HDF5/XDMF field output (fields.h5, fields.xdmf): true = displacement and pressure, "
      "false or [] = no field files, or the list of quantities to write: displacement [mm] and "
      "pressure [MPa] on the nodes; per element (the mean over its quadrature points) stress "
      "(total Cauchy stress) and effective_stress [MPa], J (det F), flux (Darcy flux "
      "-k(J) grad p) [mm/s] and permeability k(J) [mm^4/(N s)]; docs/output_fields.md.",
      [](auto& c) -> auto& { return c.output.fields; }));
  keys.push_back(bool_key<C>(
      "output.line",
      "Probe line: write line.csv and take the oscillation measures (p_mid, overshoot, "
      "oscillation) on it; false = no probe line at all (its points need not lie in the body).",
      [](auto& c) -> auto& { return c.output.line; }));
  keys.push_back(string_list_key<C>(
      "output.reactions", {},
      "Boundaries whose reaction force is written at every output (reactions.csv and the "
      "summary): the force [N] that the boundary's displacement and symmetry conditions exert "
      "on the body, summed over its nodes. Each must carry such a condition. With two or more, "
      "also their `total`, counting a node held by two of them once.",
      [](auto& c) -> auto& { return c.output.reactions; }));

  keys.push_back(bool_key<C>(
      "constraints.allow_free_rigid_modes",
      "Run although the displacement and symmetry conditions leave a rigid-body mode "
      "(translation or rotation) of the body or of a part of the mesh free; the loads must then "
      "balance exactly. Without it such a case is refused before the first step "
      "(docs/constraints.md).",
      [](auto& c) -> auto& { return c.constraints.allow_free_rigid_modes; }));
  keys.push_back(bool_key<C>(
      "constraints.allow_coincident_nodes",
      "Accept distinct mesh nodes at the same place (a deliberate crack); without it they are "
      "refused, naming the nodes.",
      [](auto& c) -> auto& { return c.constraints.allow_coincident_nodes; }));
  return keys;
}

std::vector<Key<BoundaryCondition>> build_boundary_keys() {
  using B = BoundaryCondition;
  using T = BcType;
  std::vector<Key<B>> keys;

  auto name = string_key<B>(
      "name",
      "Name of the mesh boundary (gmsh physical surface), or for a displacement condition also "
      "of a gmsh physical point or curve.",
      [](auto& b) -> auto& { return b.boundary; });
  name.required = true;
  name.non_empty = true;
  keys.push_back(name);

  auto type = choice_key<B>(
      "type", bc_names(),
      "Kind of condition: prescribed displacement component, symmetry (zero normal "
      "displacement on an axis-aligned plane), fluid pressure, outward fluid flux, nominal "
      "traction vector, nominal normal traction (positive value pushes inwards), or a rigid "
      "platen under a prescribed total force (the boundary moves as one body along `component`).",
      [](auto& b) -> auto& { return b.type; });
  type.required = true;
  keys.push_back(type);

  auto component = choice_key<B>(
      "component", component_names(),
      "Displacement component that is prescribed, or along which a rigid platen moves.",
      [](auto& b) -> auto& { return b.component; });
  component.per_type = true;
  component.need = needs({T::Displacement, T::RigidPlaten},
                         {T::Symmetry, T::Pressure, T::Flux, T::Traction, T::NormalTraction});
  keys.push_back(component);

  auto value = number_key<B>(
      "value", Range{}, "mm, MPa, mm/s or N",
      "Scale of the load curve: displacement [mm], pressure [MPa], flux [mm/s], normal "
      "traction [MPa], or a rigid platen's total force on the body along its component [N] "
      "(negative pushes toward −component; the force on the modelled part: a quarter model "
      "carries a quarter of the load, an axisymmetric one the full circle, a plane-strain one "
      "per mm of depth).",
      [](auto& b) -> auto& { return b.value; });
  value.per_type = true;
  value.need = needs({T::Displacement, T::Pressure, T::Flux, T::NormalTraction, T::RigidPlaten},
                     {T::Symmetry, T::Traction});
  keys.push_back(value);

  auto vector = vector_key<B>(
      "vector", "MPa", "Nominal traction vector, scaled by the curve.",
      [](auto& b) -> auto& { return b.vector; });
  vector.per_type = true;
  vector.need = needs({T::Traction}, {T::Displacement, T::Symmetry, T::Pressure, T::Flux,
                                      T::NormalTraction, T::RigidPlaten});
  keys.push_back(vector);

  auto curve = string_key<B>(
      "curve", "Name of an entry of [curves] scaling the condition in time; absent = constant 1.",
      [](auto& b) -> auto& { return b.curve; });
  curve.per_type = true;
  curve.need = needs({}, {T::Symmetry});
  keys.push_back(curve);
  return keys;
}

std::vector<Key<ProbeConfig>> build_probe_keys() {
  using P = ProbeConfig;
  std::vector<Key<P>> keys;
  auto name = string_key<P>(
      "name",
      "Name of the probe: letters, digits, '_' and '-'; its samples go to probe_<name>.csv. "
      "Names must differ.",
      [](auto& p) -> auto& { return p.name; });
  name.required = true;
  name.non_empty = true;
  keys.push_back(name);
  auto start = vector_key<P>(
      "start", "mm", "Start point of the probe line; must lie in the body.",
      [](auto& p) -> auto& { return p.start; });
  start.required = true;
  keys.push_back(start);
  auto end = vector_key<P>(
      "end", "mm", "End point of the probe line; must lie in the body and differ from start.",
      [](auto& p) -> auto& { return p.end; });
  end.required = true;
  keys.push_back(end);
  keys.push_back(integer_key<P>(
      "points", from_to(0, static_cast<double>(kMaxProbePoints)), {},
      "Samples: 0 = the mesh nodes on the line when it runs along the mesh, else 101 evenly "
      "spaced points; n >= 2 = n evenly spaced points (interpolated). 1 is not allowed.",
      [](auto& p) -> auto& { return p.points; }));
  return keys;
}

// ---- Markdown ---------------------------------------------------------------------------

std::string kind_name(Kind kind) {
  switch (kind) {
    case Kind::Integer:
      return "integer";
    case Kind::Number:
      return "number";
    case Kind::Boolean:
      return "boolean";
    case Kind::String:
      return "string";
    case Kind::Choice:
      return "string";
    case Kind::Vector3:
      return "array of 3 numbers";
    case Kind::StringList:
      return "array of strings";
    case Kind::Selection:
      return "boolean or array of strings";
    case Kind::Curve:
      return "array of [t, value]";
    case Kind::Expression:
      return "formula";
    case Kind::NumberList:
      return "array of numbers";
  }
  return "";
}

std::string code_list(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const auto& item : items) quoted.push_back("`" + item + "`");
  return join(quoted, ", ");
}

std::string allowed_text(const KeyInfo& key) {
  switch (key.kind) {
    case Kind::Integer:
      if (key.allowed.size() == 1) return std::to_string(key.allowed.front());
      if (!key.allowed.empty()) {
        std::vector<std::string> items;
        for (auto v : key.allowed) items.push_back(std::to_string(v));
        return "one of " + join(items, ", ");
      }
      return key.range.describe();
    case Kind::Number:
      return key.range.describe();
    case Kind::Boolean:
      return "`true`, `false`";
    case Kind::String:
      return key.non_empty ? "not empty" : "";
    case Kind::Choice:
      return "one of " + code_list(key.choices);
    case Kind::Vector3:
      return key.range.describe();
    case Kind::StringList:
      return key.choices.empty() ? "distinct names" : "each one of " + code_list(key.choices);
    case Kind::Selection:
      return "`true`, `false`, or distinct names, each one of " + code_list(key.choices);
    case Kind::Curve:
      return ">= 1 point, t strictly increasing";
    case Kind::Expression:
      return "see *Formulas*";
    case Kind::NumberList:
      return key.range.describe().empty() ? "" : "each " + key.range.describe();
  }
  return "";
}

std::string per_type_text(const KeyInfo& key) {
  std::vector<std::string> required;
  std::vector<std::string> forbidden;
  bool any_optional = false;
  for (std::size_t i = 0; i < kBcTypeCount; ++i) {
    if (key.need[i] == Need::Required) required.push_back(bc_type_names()[i]);
    if (key.need[i] == Need::Forbidden) forbidden.push_back(bc_type_names()[i]);
    if (key.need[i] == Need::Optional) any_optional = true;
  }
  std::vector<std::string> parts;
  if (!required.empty()) parts.push_back("required for " + code_list(required));
  if (any_optional) {
    if (!forbidden.empty()) parts.push_back("not allowed for " + code_list(forbidden));
    parts.push_back("optional otherwise");
  } else if (!forbidden.empty()) {
    parts.push_back("not allowed otherwise");
  }
  return join(parts, "; ");
}

std::string cell(std::string text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|')
      out += "\\|";
    else
      out += ch;
  }
  return out;
}

template <class Target>
std::string table_row(const Key<Target>& key, const std::string& shown_path,
                      const std::string& default_text) {
  return "| `" + shown_path + "` | " + kind_name(key.kind) + " | " + cell(default_text) + " | " +
         cell(allowed_text(key)) + " | " + cell(key.unit) + " | " + cell(key.help) + " |\n";
}

const char* const kTableHeader =
    "| Key | Type | Default | Allowed | Unit | Description |\n"
    "| --- | --- | --- | --- | --- | --- |\n";

std::string section_of(const std::string& path) {
  auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string{} : path.substr(0, dot);
}

std::string boundary_section_markdown() {
  std::string out = "### `[[boundary]]`\n\n";
  out +=
      "Boundary conditions, one `[[boundary]]` table each; at least one is required. With "
      "`--set`, entry i (counted from 0) is `boundary[i]`, e.g. `--set "
      "boundary[0].value=-0.1`.\n\n";
  out += kTableHeader;
  for (const auto& key : boundary_keys()) {
    std::string default_text;
    if (key.required) {
      default_text = "required";
    } else {
      default_text = per_type_text(key);
      if (key.fetch) {
        auto shown = format_value(key.fetch(BoundaryCondition{}));
        if (key.kind == Kind::String) default_text += "; default `" + shown + "`";
      }
    }
    out += table_row(key, "boundary[i]." + key.path, default_text);
  }
  return out + "\n";
}

std::string region_section_markdown() {
  std::string out = "### `[[region]]`\n\n";
  out +=
      "Materials of mesh regions, one `[[region]]` table each (none by default): `name` names a "
      "region of the mesh (a physical volume of a .msh file, or a region of the generated "
      "column), the other keys are those of `[material]`, and each key an entry leaves out is "
      "inherited from `[material]`. A mesh region without an entry uses `[material]`; a name "
      "that is not a region of the mesh is an error naming the mesh's regions. The checks of "
      "`[material]` apply to each entry (ranges, keys of a law the entry does not use, "
      "lambda + 2/3 mu > 0), with messages naming `region[i].key`. With `--set`, entry i "
      "(counted from 0) is `region[i]`, e.g. `--set region[0].permeability=2e-3` "
      "(docs/model_layer.md, *Regions*).\n\n";
  out += kTableHeader;
  out +=
      "| `region[i].name` | string | required | not empty, distinct | | Name of the mesh "
      "region. |\n";
  for (const auto& key : global_keys()) {
    if (key.path.rfind("material.", 0) != 0) continue;
    const std::string name = key.path.substr(9);
    out += table_row(key, "region[i]." + name, "inherited from `" + key.path + "`");
  }
  return out + "\n";
}

std::string probe_section_markdown() {
  std::string out = "### `[[probe]]`\n\n";
  out +=
      "Named probe lines, one `[[probe]]` table each (none by default): the solution sampled "
      "from start to end and written to `probe_<name>.csv` with the columns of `line.csv` "
      "(docs/probes.md). With `--set`, entry i (counted from 0) is `probe[i]`, e.g. `--set "
      "probe[0].points=201`.\n\n";
  out += kTableHeader;
  const ProbeConfig defaults;
  for (const auto& key : probe_keys()) {
    const std::string default_text =
        key.required ? "required" : "`" + format_value(key.fetch(defaults)) + "`";
    out += table_row(key, "probe[i]." + key.path, default_text);
  }
  return out;
}

}  // namespace

bool Range::contains(double x) const {
  if (min && !(min_open ? x > *min : x >= *min)) return false;
  if (max && !(max_open ? x < *max : x <= *max)) return false;
  return true;
}

namespace {
/// A bound as written in a rule: whole numbers without ".0" ("> 0", "in [1, 1000]").
std::string format_bound(double x) {
  if (std::isfinite(x) && x == std::trunc(x) && std::abs(x) < 1e15) {
    return std::to_string(static_cast<long long>(x));
  }
  return format_number(x);
}
}  // namespace

std::string Range::describe() const {
  if (min && max) {
    return std::string("in ") + (min_open ? "(" : "[") + format_bound(*min) + ", " +
           format_bound(*max) + (max_open ? ")" : "]");
  }
  if (min) return (min_open ? "> " : ">= ") + format_bound(*min);
  if (max) return (max_open ? "< " : "<= ") + format_bound(*max);
  return "";
}

const std::vector<Key<Config>>& global_keys() {
  static const auto keys = build_global_keys();
  return keys;
}

const std::vector<Key<BoundaryCondition>>& boundary_keys() {
  static const auto keys = build_boundary_keys();
  return keys;
}

const std::vector<Key<ProbeConfig>>& probe_keys() {
  static const auto keys = build_probe_keys();
  return keys;
}

const std::vector<std::string>& bc_type_names() {
  static const auto names = names_of(bc_names());
  return names;
}

const std::string& bc_type_name(BcType type) {
  return bc_type_names().at(static_cast<std::size_t>(type));
}

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::array<char, 64> buffer{};
  auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  std::string text(buffer.data(), result.ptr);
  auto e = text.find('e');
  if (e == std::string::npos) {
    if (text.find('.') == std::string::npos) text += ".0";
    return text;
  }
  // "1e-08" -> "1e-8", "1e+20" -> "1e20"
  std::string mantissa = text.substr(0, e);
  std::string exponent = text.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  auto first = exponent.find_first_not_of('0');
  exponent = first == std::string::npos ? "0" : exponent.substr(first);
  return mantissa + "e" + sign + exponent;
}

std::string quote(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          std::array<char, 8> hex{};
          std::snprintf(hex.data(), hex.size(), "\\u%04x", static_cast<unsigned>(ch));
          out += hex.data();
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string format_value(const Value& value) {
  struct Visitor {
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const { return format_number(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return quote(v); }
    std::string operator()(const std::array<double, 3>& v) const {
      return "[" + format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]) +
             "]";
    }
    std::string operator()(const std::vector<std::string>& v) const {
      std::vector<std::string> items;
      for (const auto& s : v) items.push_back(quote(s));
      return "[" + join(items, ", ") + "]";
    }
    std::string operator()(const std::vector<double>& v) const {
      std::vector<std::string> items;
      for (const double x : v) items.push_back(format_number(x));
      return "[" + join(items, ", ") + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

nlohmann::json value_to_json(const Value& value) {
  return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

}  // namespace biphasic::case_schema

namespace biphasic {

using namespace case_schema;

std::string case_schema_markdown() {
  std::string out;
  out += "## Key reference\n\n";
  out +=
      "Types: *integer* is a TOML integer; *number* is a TOML float, or an integer; strings "
      "with an *Allowed* list must be one of the listed words. Keys left out take the default "
      "shown. Units: mm, N, s, MPa.\n\n";

  const Config defaults;
  std::string current = "\x01";  // no section yet
  for (const auto& key : global_keys()) {
    const std::string section = key.kind == Kind::Curve ? "curves" : section_of(key.path);
    if (section != current) {
      if (current == "curves")
        out += "\n" + boundary_section_markdown();
      else if (current == "material")
        out += "\n" + region_section_markdown();
      else if (current != "\x01")
        out += "\n";
      current = section;
      out += section.empty() ? std::string("### Top level\n\n") : "### `[" + section + "]`\n\n";
      out += kTableHeader;
    }
    std::string default_text;
    if (key.required)
      default_text = "required";
    else if (key.kind == Kind::Curve)
      default_text = "none";
    else if (key.fetch)
      default_text = "`" + format_value(key.fetch(defaults)) + "`";
    out += table_row(key, key.path, default_text);
  }
  return out + "\n" + probe_section_markdown();
}

nlohmann::json config_to_json(const Config& config) {
  nlohmann::json out = nlohmann::json::object();
  out["case_file"] = config.case_file;
  for (const auto& key : global_keys()) {
    if (!key.fetch) continue;
    nlohmann::json* node = &out;
    std::string path = key.path;
    for (auto dot = path.find('.'); dot != std::string::npos; dot = path.find('.')) {
      node = &(*node)[path.substr(0, dot)];
      path.erase(0, dot + 1);
    }
    (*node)[path] = value_to_json(key.fetch(config));
  }

  nlohmann::json curves = nlohmann::json::object();
  for (const auto& [name, curve] : config.curves) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& [t, v] : curve.points) points.push_back({t, v});
    curves[name] = points;
  }
  out["curves"] = curves;

  nlohmann::json bcs = nlohmann::json::array();
  for (const auto& bc : config.bcs) {
    nlohmann::json entry = nlohmann::json::object();
    for (const auto& key : boundary_keys()) {
      if (key.per_type && key.need[static_cast<std::size_t>(bc.type)] == Need::Forbidden) continue;
      entry[key.path] = value_to_json(key.fetch(bc));
    }
    bcs.push_back(entry);
  }
  out["boundary"] = bcs;

  if (!config.regions.empty()) {
    // Each entry in full: the inherited keys with the values in use.
    nlohmann::json regions = nlohmann::json::array();
    for (const RegionConfig& region : config.regions) {
      Config one;
      one.material = region.material;
      nlohmann::json entry = nlohmann::json::object();
      entry["name"] = region.name;
      for (const auto& key : global_keys())
        if (key.fetch && key.path.rfind("material.", 0) == 0)
          entry[key.path.substr(9)] = value_to_json(key.fetch(one));
      regions.push_back(entry);
    }
    out["region"] = regions;
  }

  nlohmann::json probes = nlohmann::json::array();
  for (const auto& probe : config.output.probes) {
    nlohmann::json entry = nlohmann::json::object();
    for (const auto& key : probe_keys()) entry[key.path] = value_to_json(key.fetch(probe));
    probes.push_back(entry);
  }
  out["probe"] = probes;
  return out;
}

std::string to_string(BcType type) { return case_schema::bc_type_name(type); }

std::string to_string(ModelKind model) {
  return case_schema::name_of(case_schema::model_names(), model);
}

std::string to_string(FactorPrecision precision) {
  return case_schema::name_of(case_schema::precision_names(), precision);
}

std::string to_string(Ordering ordering) {
  return case_schema::name_of(case_schema::ordering_names(), ordering);
}

std::string to_string(FieldQuantity quantity) {
  return case_schema::name_of(case_schema::field_quantity_names(), quantity);
}

}  // namespace biphasic
