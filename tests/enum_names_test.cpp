// Each enumeration's names read back to the value they were written from, and
// only those names are accepted: the parsers and toString share one table.

#include <gtest/gtest.h>

#include "core/base/enum_names.hpp"
#include "core/domain/grid_domain.hpp"
#include "core/models/diffusion_spec.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"

using namespace morphogen;

TEST(EnumNames, EdgeModesRoundTrip) {
    for (EdgeMode m : {EdgeMode::Periodic, EdgeMode::Clamped})
        EXPECT_EQ(parseEdgeMode(toString(m)), m);
    EXPECT_EQ(toString(EdgeMode::Clamped), "clamped");
    EXPECT_EQ(edgeModeNames(), "periodic, clamped");
    // Case is not a different name; aliases read as the canonical value.
    EXPECT_EQ(parseEdgeMode("Periodic"), EdgeMode::Periodic);
    EXPECT_EQ(parseEdgeMode("wrap"), EdgeMode::Periodic);
    EXPECT_EQ(parseEdgeMode("zero_flux"), EdgeMode::Clamped);
    EXPECT_FALSE(parseEdgeMode("periodical"));
    EXPECT_FALSE(parseEdgeMode(""));
}

TEST(EnumNames, IntegratorsRoundTrip) {
    for (Integrator i : {Integrator::ExplicitEuler, Integrator::SemiImplicit})
        EXPECT_EQ(parseIntegrator(toString(i)), i);
    EXPECT_EQ(toString(Integrator::SemiImplicit), "semi_implicit");
    EXPECT_EQ(integratorNames(), "explicit_euler, semi_implicit");
    // '-' and '_' are one separator; the alias is written back canonically.
    EXPECT_EQ(parseIntegrator("semi-implicit"), Integrator::SemiImplicit);
    EXPECT_EQ(toString(*parseIntegrator("euler")), "explicit_euler");
    EXPECT_FALSE(parseIntegrator("semi implicit"));
}

TEST(EnumNames, StencilsRoundTrip) {
    for (Stencil s : {Stencil::FivePoint, Stencil::NinePoint})
        EXPECT_EQ(parseStencil(toString(s)), s);
    EXPECT_EQ(toString(Stencil::NinePoint), "9-point");
    EXPECT_EQ(stencilNames(), "5-point, 9-point");
    // The CLI's short "5" is its own alias, not a session spelling.
    EXPECT_FALSE(parseStencil("5"));
    EXPECT_EQ(parseStencil("nine_point"), Stencil::NinePoint);
}

TEST(EnumNames, JoinNamesListsInOrder) {
    EXPECT_EQ(joinNames(std::vector<std::string>{}), "");
    EXPECT_EQ(joinNames(std::vector<std::string>{"a"}), "a");
    EXPECT_EQ(joinNames(colormapNames()),
              "grey, two-colour, viridis, magma, inferno, coolwarm, custom, watercolour");
}
