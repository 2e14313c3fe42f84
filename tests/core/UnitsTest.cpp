#include "vesica/core/Units.h"

#include <gtest/gtest.h>

namespace u = vesica::units;

// Hand-checked conversions: 1 cmH2O = 98.0665 Pa; 50 ml/min = 8.333e-7 m^3/s.
TEST(Units, ClinicalConversions) {
  EXPECT_DOUBLE_EQ(u::pa_from_cmh2o(1.0), 98.0665);
  EXPECT_NEAR(u::cmh2o_from_pa(814.0), 8.3004, 1e-4);
  EXPECT_DOUBLE_EQ(u::m3_from_ml(479.0), 4.79e-4);
  EXPECT_NEAR(u::m3s_from_ml_per_min(50.0), 8.3333333e-7, 1e-13);
  EXPECT_DOUBLE_EQ(u::ml_from_mm3(1000.0), 1.0);
  EXPECT_DOUBLE_EQ(u::mm_from_m(u::m_from_mm(3.0)), 3.0);
}
