#include "opf/particles/resampling_scheme_names.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace opf {
namespace {

using PF = mrpt::bayes::CParticleFilter;

TEST(ResamplingSchemeNames, MapsTheFourNamesToMrpt) {
  EXPECT_EQ(parse_resampling_scheme("multinomial"), PF::prMultinomial);
  EXPECT_EQ(parse_resampling_scheme("residual"), PF::prResidual);
  EXPECT_EQ(parse_resampling_scheme("stratified"), PF::prStratified);
  EXPECT_EQ(parse_resampling_scheme("systematic"), PF::prSystematic);
}

TEST(ResamplingSchemeNames, RoundTrips) {
  for (const auto scheme : {PF::prMultinomial, PF::prResidual, PF::prStratified, PF::prSystematic})
    EXPECT_EQ(parse_resampling_scheme(to_string(scheme)), scheme);
  EXPECT_EQ(to_string(PF::prSystematic), "systematic");
}

TEST(ResamplingSchemeNames, UnknownNameListsTheKnownOnes) {
  for (const char* bad : {"", "Systematic", "bogus", "systematic "}) {
    try {
      parse_resampling_scheme(bad);
      FAIL() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      for (const char* name : {"multinomial", "residual", "stratified", "systematic"})
        EXPECT_NE(what.find(name), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace opf
