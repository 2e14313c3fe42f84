// The parameter catalogue is the one description of the model's parameters: for each named
// material, every catalogue parameter's key on vesica-simulate's command line and in a
// pipeline file resolves to the same value, unit and range as the material registry and the
// model card; the defaults are docs/simulate.md's "Default walls"; an earlier spelling sets
// the same value; a parameter the material's law lacks is refused (docs/parameters.md, "The
// parameter catalogue"). The calibration's names are walked in compare's tests, the Python
// keys in tests/python.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "vesica/core/Error.h"
#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/materials/MaterialRegistry.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

// A value in the parameter's range other than its default for `material` (in its unit).
double other_value(const PhysicalParameter& p, double default_value) {
  for (double v : {1.5 * default_value, 0.5 * default_value, 0.5, 2.0, 0.01, 20.0})
    if (v != default_value && p.range.contains(v)) return v;
  ADD_FAILURE() << p.name << ": no other value in " << p.range.describe(p.unit);
  return default_value;
}

double default_in_unit(const PhysicalParameter& p, const std::string& material) {
  if (!p.is_material()) return p.protocol_default();
  const double mu = catalogue_parameter("mu").default_si(material).front();
  return p.default_si(material, mu).front() / p.si_per_unit;
}

// The card of a material given through the table's keys ("mu_kpa" -> "2").
ModelCard card_through_table(const std::string& material,
                             const std::vector<std::pair<std::string, std::string>>& given) {
  SimulateSettings s;
  ParameterTable table = parameter_table(s);
  table.find("material")->assign(material);
  for (const auto& [key, text] : given) table.find(key)->assign(text);
  ModelCard card;
  card.material = resolve_material(material_spec(s.material));
  card.protocol = s.protocol;
  return card;
}

}  // namespace

TEST(ParameterCatalogue, EachParameterHasOneNameOneKeyAndAFitRangeInsideItsRange) {
  std::set<std::string> names, keys;
  for (const PhysicalParameter& p : parameter_catalogue()) {
    SCOPED_TRACE(p.name);
    EXPECT_TRUE(names.insert(p.name).second) << "name used twice";
    EXPECT_TRUE(keys.insert(p.key).second) << "key used twice";
    EXPECT_FALSE(p.help.empty());
    EXPECT_GT(p.si_per_unit, 0.0);
    if (p.fit_range) {
      EXPECT_TRUE(p.range.contains(p.fit_range->lower)) << p.range.describe(p.unit);
      EXPECT_TRUE(p.range.contains(p.fit_range->upper)) << p.range.describe(p.unit);
      EXPECT_LT(p.fit_range->lower, p.fit_range->upper);
    }
    if (p.fit_start) {
      ASSERT_TRUE(p.fit_range);
      EXPECT_GE(*p.fit_start, p.fit_range->lower);
      EXPECT_LE(*p.fit_start, p.fit_range->upper);
    }
    for (const NamedMaterial& m : named_materials()) {
      if (p.applies_to(m.name) && !p.per_branch) {
        EXPECT_TRUE(p.range.contains(default_in_unit(p, m.name)))
            << m.name << "'s default " << default_in_unit(p, m.name) << " is outside "
            << p.range.describe(p.unit);
      }
    }
  }
  // The earlier spellings of the contractility still find it.
  EXPECT_EQ(find_parameter("detrusor_kpa"), &catalogue_parameter("contractility"));
  EXPECT_EQ(find_parameter("detrusor"), &catalogue_parameter("contractility"));
}

// docs/simulate.md "Default walls", written out by hand: the bladder and the neobladder.
TEST(ParameterCatalogue, TheDefaultWallsAreTheDocumentedOnes) {
  const MaterialCard b = resolve_material({"bladder", {}});
  EXPECT_EQ(b.mu_pa, 0.6e3);
  EXPECT_EQ(b.k_pa, 0.6e6);  // K = 1000 mu
  ASSERT_TRUE(b.fibers);
  EXPECT_EQ(b.k1_pa, 125.0);
  EXPECT_EQ(b.k2, 0.02);
  ASSERT_EQ(b.branches.size(), 1u);
  EXPECT_EQ(b.branches[0].beta, 0.2);
  EXPECT_EQ(b.branches[0].tau_s, 10.0);
  EXPECT_EQ(b.contractility_pa, 100e3);
  EXPECT_EQ(b.tone_pa, 0.0);
  EXPECT_EQ(b.optimal_stretch, 3.0);
  EXPECT_EQ(b.stretch_width, 1.5);
  EXPECT_EQ(b.hill_a, 0.3);
  EXPECT_EQ(b.hill_vmax_per_s, 0.25);
  const MaterialCard n = resolve_material({"neobladder", {}});
  EXPECT_EQ(n.mu_pa, 2e3);  // docs/simulate.md "Default walls": the neobladder column
  EXPECT_EQ(n.k1_pa, 200.0);
  EXPECT_EQ(n.k2, 0.045);
  ASSERT_EQ(n.branches.size(), 1u);
  EXPECT_EQ(n.branches[0].beta, 0.2);
  EXPECT_EQ(n.branches[0].tau_s, 10.0);
  EXPECT_FALSE(n.has_muscle());  // voided by straining
  // The plain laws: the thesis's matrix, its branch for maxwell, fibers of 10 kPa.
  EXPECT_EQ(resolve_material({"neo-hookean", {}}).mu_pa, 5e3);
  EXPECT_TRUE(resolve_material({"neo-hookean", {}}).branches.empty());
  EXPECT_EQ(resolve_material({"maxwell", {}}).branches[0].beta, 0.15);
  EXPECT_EQ(resolve_material({"fibers", {}}).k1_pa, 10e3);
}

TEST(ParameterCatalogue, EveryKeyResolvesToTheSameValueUnitAndRangeForEachMaterial) {
  SimulateSettings bound;
  const ParameterTable cli = parameter_table(bound);
  const ParameterTable pipeline = parameter_table();  // the runner's copy
  for (const NamedMaterial& m : named_materials()) {
    for (const PhysicalParameter& p : parameter_catalogue()) {
      SCOPED_TRACE(m.name + " " + p.key);
      for (const ParameterTable* table : {&cli, &pipeline}) {
        const Parameter* entry = table->find(p.key);
        ASSERT_NE(entry, nullptr);
        EXPECT_EQ(entry->unit, p.unit);
        EXPECT_NE(entry->accepted().find(p.range.describe(p.unit)), std::string::npos)
            << entry->accepted();
      }
      const ModelCard defaults = card_through_table(m.name, {});
      if (!p.applies_to(m.name)) {
        EXPECT_TRUE(card_value_si(defaults, p).empty());
        EXPECT_THROW(card_through_table(m.name, {{p.key, "0.5"}}), Error);
        continue;
      }
      if (p.per_branch) {
        const std::string text = p.name == "beta" ? "0.3,0.05" : "2,20";
        const std::string other = p.name == "beta" ? "tau_s" : "beta";
        const ModelCard card = card_through_table(
            m.name, {{p.key, text}, {other, p.name == "beta" ? "2,20" : "0.3,0.05"}});
        const std::vector<double> expected =
            p.name == "beta" ? std::vector<double>{0.3, 0.05} : std::vector<double>{2.0, 20.0};
        EXPECT_EQ(card_value_si(card, p), expected);
        continue;
      }
      const double d = default_in_unit(p, m.name);
      ASSERT_EQ(card_value_si(defaults, p).size(), 1u);
      EXPECT_DOUBLE_EQ(card_value_si(defaults, p).front(), d * p.si_per_unit);
      const double v = other_value(p, d);
      const ModelCard given = card_through_table(m.name, {{p.key, format_number(v)}});
      EXPECT_DOUBLE_EQ(card_value_si(given, p).front(), v * p.si_per_unit);
      if (!p.old_key.empty()) {
        const ModelCard old = card_through_table(m.name, {{p.old_key, format_number(v)}});
        EXPECT_EQ(card_value_si(old, p), card_value_si(given, p));
      }
    }
  }
}

TEST(ParameterCatalogue, TheBulkModulusFollowsAGivenShearModulus) {
  // K = 1000 mu unless given (docs/physics.md §2.7): mu 2 kPa gives K 2 MPa.
  const ModelCard card = card_through_table("bladder", {{"mu_kpa", "2"}});
  EXPECT_EQ(card.material.k_pa, 2e6);
}
