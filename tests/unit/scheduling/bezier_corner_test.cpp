// Spec §10.1 row "Bezier pair": the §5.7 numbers, the printed Eq. 9 breaking G1, homothety,
// the graph-limit 4/3 peak, maximum deviation |epsilon| at S2, monotone deviation in epsilon.
#include "core/scheduling/bezier_corner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace bladeaxis::scheduling {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double directionOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}

// Vertical distance of the curve from the polyline through P2 with angles alpha, beta.
double deviationAt(const BezierPair& pair, const Vec2& p2, double alpha, double beta, double s) {
    if (s <= pair.sBegin() || s >= pair.sEnd()) {
        return 0.0; // outside the span the smoothed path is the polyline
    }
    const double line = p2.y() + std::tan(s < p2.x() ? alpha : beta) * (s - p2.x());
    return evaluatePair(pair, s).value - line;
}

TEST(BezierCorner, CorrectedEquation9MatchesTheSpecNumbers) {
    const double alpha = 10.0 * kDeg;
    const double beta = 50.0 * kDeg;
    const BezierPair pair = euclideanCornerPair(Vec2::Zero(), alpha, beta, 0.5);
    EXPECT_NEAR(pair.first.control[0].x(), -2.6646, 5e-5);
    EXPECT_NEAR(pair.first.control[0].y(), -0.4698, 5e-5);
    EXPECT_NEAR(pair.second.control[1].x(), 0.8138, 5e-5);
    EXPECT_NEAR(pair.second.control[1].y(), 0.9698, 5e-5);
    EXPECT_NEAR(pair.first.control[0].norm(), 2.7057, 5e-5); // d1 (E9)
    // Closed forms of §5.2 at 1e-9: B_i1 and B_j1 as line intersections, equal legs.
    const double gamma = 30.0 * kDeg;
    const Vec2 bi1(0.5 / (std::tan(alpha) - std::tan(gamma)),
                   0.5 * std::tan(alpha) / (std::tan(alpha) - std::tan(gamma)));
    const Vec2 bj1(0.5 / (std::tan(beta) - std::tan(gamma)),
                   0.5 * std::tan(beta) / (std::tan(beta) - std::tan(gamma)));
    EXPECT_NEAR((pair.first.control[1] - bi1).norm(), 0.0, 1e-9);
    EXPECT_NEAR((pair.second.control[1] - bj1).norm(), 0.0, 1e-9);
    EXPECT_EQ(pair.first.control[1], pair.first.control[2]); // double inner points (E2)
    EXPECT_EQ(pair.second.control[1], pair.second.control[2]);
    EXPECT_NEAR((pair.first.control[1] - pair.first.control[0]).norm(),
                (pair.first.control[3] - pair.first.control[1]).norm(), 1e-12);
    EXPECT_NEAR((pair.second.control[1] - pair.second.control[0]).norm(),
                (pair.second.control[3] - pair.second.control[1]).norm(), 1e-12);
    // G1 at the three joints and G2 (zero curvature) at all four.
    EXPECT_NEAR(directionOf(pair.first.firstDerivative(0.0)), alpha, 1e-12);
    EXPECT_NEAR(directionOf(pair.first.firstDerivative(1.0)), gamma, 1e-12);
    EXPECT_NEAR(directionOf(pair.second.firstDerivative(0.0)), gamma, 1e-12);
    EXPECT_NEAR(directionOf(pair.second.firstDerivative(1.0)), beta, 1e-12);
    for (const CubicBezier* c : {&pair.first, &pair.second}) {
        EXPECT_NEAR(secondDerivativeAt(*c, 0.0), 0.0, 1e-9);
        EXPECT_NEAR(secondDerivativeAt(*c, 1.0), 0.0, 1e-9);
    }
}

// Documented erratum E5-E8: the printed Eq. 9 (with the printed tan(beta) and gamma factors)
// gives the printed numbers of §5.7 and a first cubic ending at 50 deg while the second starts
// at -130 deg: G1 is broken. The test keeps the printed formulas to show why they are wrong.
TEST(BezierCorner, PrintedEquation9BreaksG1) {
    const double a = 10.0 * kDeg, b = 50.0 * kDeg, g = 30.0 * kDeg, e = 0.5;
    const double k = std::cos(a) + std::cos(b);
    const Vec2 bi0(e * std::cos(a) * k / std::sin(b - a), e * std::sin(a) * k / std::sin(b - a));
    const Vec2 bi1(e / (std::tan(a) - std::tan(b)), e * std::tan(a) / (std::tan(a) - std::tan(b)));
    const Vec2 bi3(0.0, e);
    const Vec2 bj1(e / (std::tan(g) - std::tan(b)), e * std::tan(g) / (std::tan(g) - std::tan(b)));
    EXPECT_NEAR(bi0.x(), 1.2468, 5e-5);
    EXPECT_NEAR(bi0.y(), 0.2198, 5e-5);
    EXPECT_NEAR(bj1.x(), -0.8138, 5e-5);
    EXPECT_NEAR(bj1.y(), -0.4698, 5e-5);
    const double printedD1 = e * k / std::sin(b - a); // Eq. 11 as printed (E9)
    EXPECT_NEAR(printedD1, 1.2660, 5e-5);             // = |P2 B_i1| of the corrected points
    EXPECT_LT(printedD1, 2.7057);                     // the true d1 = |P2 B_i0|
    const CubicBezier first{{bi0, bi1, bi1, bi3}};
    const CubicBezier second{{bi3, bj1, bj1, Vec2(1.9102, 1.1029)}};
    EXPECT_NEAR(directionOf(first.firstDerivative(1.0)), 50.0 * kDeg, 1e-9);
    EXPECT_NEAR(directionOf(second.firstDerivative(0.0)), -130.0 * kDeg, 1e-9);
}

TEST(BezierCorner, MaximumDeviationIsEpsilonReachedAtTheCorner) {
    const Vec2 p2(3.0, 1.0);
    for (const auto& [alpha, beta, eps] :
         {std::tuple{0.1, 0.6, 0.2}, std::tuple{0.9, 0.2, -0.15}}) {
        const BezierPair pair = euclideanCornerPair(p2, alpha, beta, eps);
        EXPECT_NEAR(deviationAt(pair, p2, alpha, beta, p2.x()), eps, 1e-12);
        double worst = 0.0;
        for (int k = 0; k <= 1000; ++k) {
            const double s = pair.sBegin() + (pair.sEnd() - pair.sBegin()) * k / 1000.0;
            const double d = deviationAt(pair, p2, alpha, beta, s);
            EXPECT_GE(d * eps, -1e-15); // on the corner's side
            worst = std::max(worst, std::abs(d));
        }
        EXPECT_LE(worst, std::abs(eps) + 1e-12);
        EXPECT_GT(worst, 0.99 * std::abs(eps));
    }
}

TEST(BezierCorner, DeviationGrowsWithEpsilonSoBisectionIsValid) {
    const Vec2 p2(0.0, 0.0);
    const double alpha = 0.05, beta = 0.4;
    for (double s = -1.5; s <= 1.5; s += 0.1) {
        double previous = 0.0;
        for (double eps = 0.01; eps <= 0.2; eps += 0.01) {
            const double d =
                deviationAt(euclideanCornerPair(p2, alpha, beta, eps), p2, alpha, beta, s);
            EXPECT_GE(d, previous - 1e-13) << s << " " << eps;
            previous = d;
        }
    }
}

TEST(BezierCorner, PeakCurvatureTimesEpsilonIsConstantUnderHomothety) {
    double reference = 0.0;
    for (double eps : {0.01, 0.05, 0.2}) {
        const BezierPair pair = euclideanCornerPair(Vec2(1.0, 2.0), 0.1, 0.7, eps);
        double peak = 0.0;
        for (int k = 0; k <= 2000; ++k) {
            peak = std::max(peak, std::abs(secondDerivativeAt(pair.first, k / 2000.0)));
        }
        reference = reference == 0.0 ? peak * eps : reference;
        EXPECT_NEAR(peak * eps, reference, 1e-9 * reference);
    }
}

TEST(BezierCorner, GraphLimitPeakIsFourThirdsOfTheSlopeChangeOverTheHalfSpan) {
    const double k1 = 0.01, k2 = 0.05, eps = 0.02;
    const BezierPair pair = graphLimitCornerPair(Vec2(5.0, 1.0), k1, k2, eps);
    const double h = 2.0 * eps / (k2 - k1);
    EXPECT_NEAR(pair.sEnd() - pair.sBegin(), 4.0 * h, 1e-12);
    // t = 1/2 is the peak of theta'' = (2 eps / 3 h^2) t(1-t) / (1 - 2t + 2t^2)^3.
    const double peak = std::abs(secondDerivativeAt(pair.first, 0.5));
    EXPECT_NEAR(peak, 4.0 * eps / (3.0 * h * h), 1e-12);
    EXPECT_NEAR(peak * (2.0 * h) / (k2 - k1), 4.0 / 3.0, 1e-12);
    EXPECT_GE(peak, std::abs(secondDerivativeAt(pair.first, 0.45)));
    // The Euclidean form in the rad/mm plane approaches the graph limit for small slopes.
    const BezierPair euclid =
        euclideanCornerPair(Vec2(5.0, 1.0), std::atan(k1), std::atan(k2), eps);
    double euclidPeak = 0.0;
    for (int k = 0; k <= 2000; ++k) {
        euclidPeak = std::max(euclidPeak, std::abs(secondDerivativeAt(euclid.first, k / 2000.0)));
    }
    EXPECT_NEAR(euclidPeak / peak, 1.0, 0.005);
}

TEST(BezierCorner, GeometricLimitUsesTheCorrectedLegs) {
    const double alpha = 10.0 * kDeg, beta = 50.0 * kDeg;
    const double limit = euclideanEpsilonLimit(alpha, beta, 4.0, 10.0, 0.5, 0.5);
    const BezierPair pair = euclideanCornerPair(Vec2::Zero(), alpha, beta, limit);
    EXPECT_NEAR(pair.first.control[0].norm(), 2.0, 1e-12); // d1 = l1 / 2 binds
    EXPECT_LE(pair.second.control[3].norm(), 5.0 + 1e-12);
    EXPECT_NEAR(graphLimitEpsilonLimit(0.0, 0.04, 10.0, 20.0, 0.5, 1.0), 0.5 * 2.5 * 0.04, 1e-15);
}

// [X] Plateau corner: theta'' = A (1 - v^4). The analytic properties its use relies on, checked
// numerically against finite differences of the evaluated curve.
TEST(PlateauCorner, IsOneTimeSmoothAndTurnsTheSlopeWithThetaSecondFromItsValues) {
    const PlateauCorner corner{Vec2(5.0, 1.0), 0.02, 0.07, 12.0};
    const double h = 1e-3;
    for (double s = corner.sBegin() + 2.0 * h; s < corner.sEnd() - 2.0 * h; s += 0.37) {
        const GraphPoint p = corner.at(s);
        const GraphPoint before = corner.at(s - h);
        const GraphPoint after = corner.at(s + h);
        EXPECT_NEAR(p.first, (after.value - before.value) / (2.0 * h), 1e-8);
        EXPECT_NEAR(p.second, (after.first - before.first) / (2.0 * h), 1e-8);
        EXPECT_GE(p.second, 0.0); // one sign: the slope rises monotonically from k1 to k2
        EXPECT_GE(p.first, corner.k1 - 1e-15);
        EXPECT_LE(p.first, corner.k2 + 1e-15);
    }
}

TEST(PlateauCorner, MaximumDeviationIsEpsilonAtTheCornerAndShrinksTowardsTheEnds) {
    for (const auto& [k1, k2] : {std::pair{0.01, 0.05}, {0.08, 0.0}, {0.0, 0.3}}) {
        const PlateauCorner corner{Vec2(0.0, 0.0), k1, k2, 7.5};
        EXPECT_NEAR(corner.at(0.0).value, corner.epsilon(), 1e-15);
        double previous = std::abs(corner.epsilon());
        for (double a = 0.25; a <= 7.5; a += 0.25) {
            for (double side : {-1.0, 1.0}) {
                const double line = (side < 0.0 ? k1 : k2) * side * a;
                const double deviation = std::abs(corner.at(side * a).value - line);
                EXPECT_LE(deviation, previous + 1e-15);
            }
            previous = std::abs(corner.at(a).value - k2 * a);
        }
        EXPECT_NEAR(previous, 0.0, 1e-15);
    }
}

// §5.6 for this profile: the peak is 1.25 x the least possible theta'' (constant) that turns
// the slope by the same amount over the same span 2W; the Bezier pair's is 8/3 x.
TEST(PlateauCorner, PeakIsFiveQuartersOfTheLeastPossibleForItsSpan) {
    const PlateauCorner corner{Vec2(1.0, 2.0), 0.01, 0.05, 4.0};
    double peak = 0.0;
    for (double s = corner.sBegin(); s <= corner.sEnd(); s += 1e-3) {
        peak = std::max(peak, std::abs(corner.at(s).second));
    }
    const double least = (corner.k2 - corner.k1) / (2.0 * corner.halfWidth);
    EXPECT_NEAR(peak / least, 1.25, 1e-9);
    EXPECT_NEAR(corner.peak(), peak, 1e-12);
}

// Homothety (§5.3 for this profile): at a fixed v the deviation is proportional to W, so it is
// non-decreasing in W at every S and the exact rule may bound W sample by sample.
TEST(PlateauCorner, DeviationGrowsWithTheHalfWidth) {
    for (double a = -6.0; a <= 6.0; a += 0.5) {
        double previous = 0.0;
        for (double w = 0.5; w <= 8.0; w += 0.25) {
            const PlateauCorner corner{Vec2(0.0, 0.0), 0.0, 0.1, w};
            const double deviation = corner.at(a).value - (a < 0.0 ? 0.0 : 0.1 * a);
            EXPECT_GE(deviation, previous - 1e-15) << "a " << a << " w " << w;
            previous = deviation;
        }
    }
    EXPECT_NEAR(plateauHalfWidth(0.0, 0.1, PlateauCorner{Vec2(0.0, 0.0), 0.0, 0.1, 3.0}.epsilon()),
                3.0, 1e-14);
}

} // namespace
} // namespace bladeaxis::scheduling

namespace bladeaxis::scheduling {
namespace {

// Signed distance of `point` from the line through `origin` with direction `angle`.
double offLine(const Vec2& point, const Vec2& origin, double angle) {
    const Vec2 d = point - origin;
    return d.x() * std::sin(angle) - d.y() * std::cos(angle);
}

double angleGap(double a, double b) {
    return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

// Spec §5.7 re-established: 20 000 random corners (alpha, beta in [0, 1.45] rad, random P2 and
// segment lengths, epsilon in (0, epsilon_geo]) checked against every row of its table, on the
// control points and on 64 curve points per cubic. Tolerances are relative to the corner's size.
TEST(BezierCorner, TwentyThousandRandomCornersMeetEveryPropertyOfTheSpecTable) {
    std::mt19937_64 random(5707);
    std::uniform_real_distribution<double> angle(0.0, 1.45), coordinate(-50.0, 50.0),
        length(0.5, 60.0), fraction(1e-3, 1.0);
    std::size_t corners = 0;
    while (corners < 20000) {
        const double alpha = angle(random), beta = angle(random);
        if (std::abs(beta - alpha) < 1e-3) {
            continue; // no corner to smooth
        }
        ++corners;
        const Vec2 p2(coordinate(random), coordinate(random));
        const double l1 = length(random), l2 = length(random);
        const double limit = euclideanEpsilonLimit(alpha, beta, l1, l2, 0.5, 0.5);
        const bool atLimit = corners % 4 == 0; // a quarter exactly at epsilon_geo
        const double magnitude = atLimit ? limit : fraction(random) * limit;
        const double eps = beta > alpha ? magnitude : -magnitude;
        const BezierPair pair = euclideanCornerPair(p2, alpha, beta, eps);
        const auto& bi = pair.first.control;
        const auto& bj = pair.second.control;
        const double gamma = 0.5 * (alpha + beta);
        const double scale = std::max({1.0, p2.norm(), l1, l2});
        SCOPED_TRACE(::testing::Message() << "corner " << corners << " alpha " << alpha << " beta "
                                          << beta << " eps " << eps);
        // B_i0, B_i1 on P1P2; B_j1, B_j3 on P2P3; B_i1, B_i3, B_j1 on the line of direction gamma.
        ASSERT_LT(std::abs(offLine(bi[0], p2, alpha)), 1e-12 * scale);
        ASSERT_LT(std::abs(offLine(bi[1], p2, alpha)), 1e-12 * scale);
        ASSERT_LT(std::abs(offLine(bj[1], p2, beta)), 1e-12 * scale);
        ASSERT_LT(std::abs(offLine(bj[3], p2, beta)), 1e-12 * scale);
        ASSERT_LT(std::abs(offLine(bi[1], bi[3], gamma)), 1e-12 * scale);
        ASSERT_LT(std::abs(offLine(bj[1], bi[3], gamma)), 1e-12 * scale);
        // Equal legs and the joint B_i3 = B_j0.
        ASSERT_NEAR((bi[1] - bi[0]).norm(), (bi[3] - bi[1]).norm(), 1e-12 * scale);
        ASSERT_NEAR((bj[1] - bj[0]).norm(), (bj[3] - bj[1]).norm(), 1e-12 * scale);
        ASSERT_EQ(bi[3], bj[0]);
        // Tangents alpha at B_i0, beta at B_j3, gamma on both sides of B_i3; zero curvature at
        // the four joints.
        ASSERT_LT(angleGap(directionOf(pair.first.firstDerivative(0.0)), alpha), 1e-9);
        ASSERT_LT(angleGap(directionOf(pair.first.firstDerivative(1.0)), gamma), 1e-9);
        ASSERT_LT(angleGap(directionOf(pair.second.firstDerivative(0.0)), gamma), 1e-9);
        ASSERT_LT(angleGap(directionOf(pair.second.firstDerivative(1.0)), beta), 1e-9);
        for (const CubicBezier* cubic : {&pair.first, &pair.second}) {
            for (double t : {0.0, 1.0}) {
                const Vec2 d1 = cubic->firstDerivative(t);
                const Vec2 d2 = cubic->secondDerivative(t);
                const double curvature =
                    (d1.x() * d2.y() - d1.y() * d2.x()) / std::pow(d1.norm(), 3.0);
                ASSERT_LT(std::abs(curvature) * std::abs(eps), 1e-9);
            }
        }
        // d1 <= l1/2 and d2 <= l2/2 (exactly at the limit for epsilon_geo).
        ASSERT_LE((bi[0] - p2).norm(), 0.5 * l1 * (1.0 + 1e-12));
        ASSERT_LE((bj[3] - p2).norm(), 0.5 * l2 * (1.0 + 1e-12));
        // On the curve: a graph (S increasing), theta non-decreasing, one-signed curvature, on
        // the corner's side of the polyline, at most |epsilon| from it, |epsilon| at S2.
        double previousS = -std::numeric_limits<double>::infinity();
        double previousTheta = -std::numeric_limits<double>::infinity();
        double deepest = 0.0;
        for (const CubicBezier* cubic : {&pair.first, &pair.second}) {
            for (int k = 0; k <= 64; ++k) {
                const double t = k / 64.0;
                const Vec2 p = cubic->point(t);
                const Vec2 d1 = cubic->firstDerivative(t);
                const Vec2 d2 = cubic->secondDerivative(t);
                ASSERT_GT(d1.x(), 0.0) << t;
                ASSERT_GE(p.x(), previousS - 1e-12 * scale) << t;
                ASSERT_GE(p.y(), previousTheta - 1e-12 * scale) << t;
                previousS = p.x();
                previousTheta = p.y();
                ASSERT_GE((d1.x() * d2.y() - d1.y() * d2.x()) * eps, -1e-12 * scale * scale);
                const double line =
                    p2.y() + std::tan(p.x() < p2.x() ? alpha : beta) * (p.x() - p2.x());
                const double deviation = p.y() - line;
                ASSERT_GE(deviation * eps, -1e-12 * scale * std::abs(eps)) << t;
                ASSERT_LE(std::abs(deviation), std::abs(eps) + 1e-12 * scale) << t;
                deepest = std::max(deepest, std::abs(deviation));
            }
        }
        ASSERT_NEAR(deepest, std::abs(eps), 1e-12 * scale); // reached at B_i3 (t = 1, S = S2)
    }
}

} // namespace
} // namespace bladeaxis::scheduling
