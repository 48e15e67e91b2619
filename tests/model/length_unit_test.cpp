// SPDX-License-Identifier: MIT
// A STEP or IGES file's length unit, read from its text (length_unit.h).
#include "test_util.h"

#include <seamless/model/length_unit.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

// A STEP DATA section whose first unit context names `unit` (#3) as its length unit.
std::string step_with(const std::string& units) {
    return "ISO-10303-21;\nHEADER;\nFILE_NAME('a;b','#1=x;',(''),(''),'','','');\nENDSEC;\n"
           "DATA;\n/* #9 = SI_UNIT(.KILO.,.METRE.); */\n"
           "#1 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3)\n"
           "  GLOBAL_UNIT_ASSIGNED_CONTEXT ( ( #2, #3 ) ) REPRESENTATION_CONTEXT('it''s',''));\n"
           "#2 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );\n" +
           units +
           "#7 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#8)) "
           "REPRESENTATION_CONTEXT('',''));\n"
           "#8 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.CENTI.,.METRE.) );\nENDSEC;\n";
}

// An IGES global section (columns 1-72, 'G' in column 73) of `params`.
std::string iges_with(const std::string& params) {
    std::string out = std::string(72, ' ') + "S      1\n";
    for (size_t i = 0; i < params.size(); i += 72) {
        std::string line = params.substr(i, 72);
        line.resize(72, ' ');
        out += line + "G" + std::string(7, ' ') + "\n";
    }
    return out;
}

} // namespace

TEST_CASE("STEP length units: SI prefixes, conversion-based units, the first context's",
          "[model][units]") {
    CHECK(step_length_unit(step_with(
              "#3 = ( LENGTH_UNIT ( ) NAMED_UNIT ( * ) SI_UNIT ( .MILLI., .METRE. ) );\n")) ==
          0.001);
    CHECK(step_length_unit(step_with("#3=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));\n")) == 1);
    CHECK(step_length_unit(
              step_with("#3 = ( CONVERSION_BASED_UNIT('INCH',#4) LENGTH_UNIT() NAMED_UNIT(#6) );\n"
                        "#4 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#5);\n"
                        "#5 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n")) ==
          Approx(0.0254).epsilon(1e-15));
    // No length unit in the first context: the next context's.
    CHECK(step_length_unit(step_with("#3 = ( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) );\n")) == 0.01);
    CHECK(step_length_unit("ISO-10303-21;\nDATA;\n#1=CARTESIAN_POINT('',(0.,0.,0.));\n") == 0);
    CHECK(step_length_unit("#1=(GLOBAL_UNIT_ASSIGNED_CONTEXT((#1)));") == 0); // no loop
}

TEST_CASE("IGES length units: the unit flag, or the unit name", "[model][units]") {
    const std::string head = "1H,,1H;,4HPART,8Hpart.igs,4HTEST,3H1.0,32,38,6,308,15,4HPART,1.0,";
    CHECK(iges_length_unit(iges_with(head + "2,2HMM,1,1.0,13H230101.120000,0.01,100.0;")) == 0.001);
    CHECK(iges_length_unit(iges_with(head + "1,4HINCH,1,1.0,13H230101.120000,0.01,100.0;")) ==
          0.0254);
    CHECK(iges_length_unit(iges_with(head + "3,2HCM,1,1.0;")) == 0.01);
    // Default delimiters (empty parameters 1 and 2) and a Hollerith string holding them.
    CHECK(iges_length_unit(iges_with(",,4HA,;B,8Hpart.igs,4HTEST,3H1.0,32,38,6,308,15,4HPART,"
                                     "1.0,6,1HM,1,1.0;")) == 1);
    CHECK(iges_length_unit(iges_with("1H,,1H;,4HPART;")) == 0);
    CHECK(iges_length_unit("") == 0);
}

TEST_CASE("Length units of bundled and corpus files", "[model][units][heavy]") {
    CHECK(file_length_unit(test::model_path("cad/splinecage.stp")) == 0.001);
    CHECK(file_length_unit(test::model_path("cad/sunglasses_lens.igs")) == 0.0254);
    CHECK(file_length_unit(test::model_path("cad/bug28366_fuselage.json")) == 0);
    const auto corpus = test::shared_dir() / "models" / "cad-corpus";
    CHECK(file_length_unit(corpus / "nist_nist_ctc_05_asme1_ap242-e1.stp") ==
          Approx(0.0254).epsilon(1e-15));
    CHECK(file_length_unit(corpus / "occt_as1-oc-214-mat.stp") == 0.001);
}
