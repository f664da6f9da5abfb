// Fresnel, Snell and Beer-Lambert against textbook values (RENDERING.md §6).
#include <cmath>

#include <gtest/gtest.h>

#include "dielectric.h"

namespace vkrt::cpu {
namespace {

TEST(Dielectric, NormalIncidenceReflectance) {
    // ((n1 - n2) / (n1 + n2))^2: 0.04 for glass, the same from either side.
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.0f, 1.5f), 0.04f, 1e-7f);
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f, 1.0f), 0.04f, 1e-7f);
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.0f, 1.33f), std::pow(0.33f / 2.33f, 2.0f), 1e-7f);
}

TEST(Dielectric, EqualIndicesAreInvisibleExactly) {
    for (float c : {0.0f, 0.3f, 1.0f}) EXPECT_EQ(fresnelDielectric(c, 1.0f, 1.0f), 0.0f);
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.8f, 0.2f));
    EXPECT_EQ(refractDirection(d, {0, 1, 0}, 1.0f, 1.0f), d);
}

TEST(Dielectric, TotalInternalReflection) {
    // Critical angle from glass 1.5 into air: sin = 1/1.5, cos = 0.745.
    EXPECT_EQ(fresnelDielectric(0.70f, 1.5f, 1.0f), 1.0f);
    EXPECT_EQ(fresnelDielectric(0.0f, 1.5f, 1.0f), 1.0f);
    EXPECT_LT(fresnelDielectric(0.76f, 1.5f, 1.0f), 1.0f);
}

TEST(Dielectric, BrewsterAngleLeavesOnlyTheSPolarisation) {
    // At Brewster's angle tan(theta) = n2/n1 the p reflectance vanishes: F = rs^2 / 2, and for
    // glass rs^2 = cos^2(theta_i + theta_t)... = ((n1^2 - n2^2)/(n1^2 + n2^2))^2.
    const double n1 = 1.0, n2 = 1.5;
    const double theta = std::atan(n2 / n1);
    const double rs2 = std::pow((n1 * n1 - n2 * n2) / (n1 * n1 + n2 * n2), 2.0);
    EXPECT_NEAR(fresnelDielectric(float(std::cos(theta)), 1.0f, 1.5f), rs2 / 2.0, 1e-6);
}

TEST(Dielectric, GrazingIncidenceReflectsEverything) { EXPECT_NEAR(fresnelDielectric(0.0f, 1.0f, 1.5f), 1.0f, 1e-6f); }

TEST(Dielectric, ReciprocityBetweenTheTwoSides) {
    // F(theta_i; n1 -> n2) = F(theta_t; n2 -> n1).
    for (double ci : {0.95, 0.8, 0.5, 0.2}) {
        const double st = std::sqrt(1 - ci * ci) / 1.5;
        const double ct = std::sqrt(1 - st * st);
        EXPECT_NEAR(fresnelDielectric(float(ci), 1.0f, 1.5f), fresnelDielectric(float(ct), 1.5f, 1.0f), 2e-6);
    }
}

TEST(Dielectric, RefractionObeysSnell) {
    const glm::vec3 n(0, 0, 1);
    for (float n2 : {1.33f, 1.5f, 2.4f}) {
        const glm::vec3 d = glm::normalize(glm::vec3(0.6f, 0.2f, -1.0f));
        const glm::vec3 t = refractDirection(d, n, 1.0f, n2);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
        const float sinI = glm::length(glm::cross(d, n)), sinT = glm::length(glm::cross(t, n));
        EXPECT_NEAR(1.0f * sinI, n2 * sinT, 1e-5f);
        EXPECT_LT(glm::dot(t, n), 0.0f);                       // continues through the surface
        EXPECT_NEAR(glm::dot(glm::cross(d, n), t), 0.0f, 1e-6f);  // in the plane of incidence
    }
}

TEST(Dielectric, BeerLambertIsPerUnitTransmittance) {
    const glm::vec3 t = beerLambert({0.5f, 0.9f, 1.0f}, 2.0f);
    EXPECT_FLOAT_EQ(t.x, 0.25f);
    EXPECT_FLOAT_EQ(t.y, 0.81f);
    EXPECT_EQ(t.z, 1.0f);
    EXPECT_EQ(beerLambert({0.3f, 0.3f, 0.3f}, 0.0f), glm::vec3(1.0f));
}

}  // namespace
}  // namespace vkrt::cpu
