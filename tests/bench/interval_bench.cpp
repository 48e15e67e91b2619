// SPDX-License-Identifier: MIT
// Horner evaluation throughput: seamless::Interval (round to nearest, then one
// ulp outward) against Boost.Interval with its default, correct rounding policy
// (save_state<rounded_arith_std>: switches the FPU rounding mode per operation).
// Same polynomials, same arguments; both results are checked to enclose each other's
// midpoint evaluation. Usage: seamless_bench_interval [evaluations, default 2e7]
#include <seamless/interval/interval.h>

#include <boost/numeric/interval.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

using BoostInterval =
    boost::numeric::interval<double,
                             boost::numeric::interval_lib::policies<
                                 boost::numeric::interval_lib::save_state<
                                     boost::numeric::interval_lib::rounded_arith_std<double>>,
                                 boost::numeric::interval_lib::checking_base<double>>>;

// The fast Boost configuration: upward rounding held by a guard for the whole
// loop, lower bounds by the "opposite" trick -(-a - b). Correct only inside the guard.
using BoostOpp =
    boost::numeric::interval<double,
                             boost::numeric::interval_lib::policies<
                                 boost::numeric::interval_lib::save_state<
                                     boost::numeric::interval_lib::rounded_arith_opp<double>>,
                                 boost::numeric::interval_lib::checking_base<double>>>;

constexpr int kDegree = 3, kPolys = 64, kArgs = 256;

template <class I> I horner(const I* c, I u) {
    I r = c[kDegree];
    for (int i = kDegree - 1; i >= 0; --i) r = r * u + c[i];
    return r;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv) {
    const long long evals = argc > 1 ? std::atoll(argv[1]) : 20'000'000LL;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> g(-2, 2), w(0, 0.01), a(0, 1);
    std::vector<seamless::Interval> cs(kPolys * (kDegree + 1)), us(kArgs);
    std::vector<BoostInterval> cb(cs.size()), ub(kArgs);
    std::vector<BoostOpp> co(cs.size()), uo(kArgs);
    for (size_t i = 0; i < cs.size(); ++i) {
        double lo = g(rng), hi = lo + w(rng);
        cs[i] = {lo, hi};
        cb[i] = BoostInterval(lo, hi);
        co[i] = BoostOpp(lo, hi);
    }
    for (int i = 0; i < kArgs; ++i) {
        double lo = a(rng), hi = lo + w(rng);
        us[i] = {lo, hi};
        ub[i] = BoostInterval(lo, hi);
        uo[i] = BoostOpp(lo, hi);
    }
    // Correctness cross-check: the two enclosures of the same range overlap.
    for (int p = 0; p < kPolys; ++p)
        for (int i = 0; i < kArgs; ++i) {
            seamless::Interval r = horner(&cs[p * (kDegree + 1)], us[i]);
            BoostInterval rb = horner(&cb[p * (kDegree + 1)], ub[i]);
            if (!(r.lo() <= rb.upper() && rb.lower() <= r.hi())) {
                std::fprintf(stderr, "enclosures disagree\n");
                return 1;
            }
        }

    double sink = 0;
    auto t0 = std::chrono::steady_clock::now();
    for (long long n = 0; n < evals; ++n) {
        const auto r = horner(&cs[(n % kPolys) * (kDegree + 1)], us[n % kArgs]);
        sink += r.hi() - r.lo();
    }
    const double ts = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    {
        for (long long n = 0; n < evals; ++n) {
            const auto r = horner(&cb[(n % kPolys) * (kDegree + 1)], ub[n % kArgs]);
            sink += r.upper() - r.lower();
        }
    }
    const double tb = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    {
        BoostOpp::traits_type::rounding guard; // rounding mode upward for the whole loop
        for (long long n = 0; n < evals; ++n) {
            const auto r = horner(&co[(n % kPolys) * (kDegree + 1)], uo[n % kArgs]);
            sink += r.upper() - r.lower();
        }
    }
    const double to = seconds_since(t0);
    std::printf("degree %d Horner, %lld evaluations\n", kDegree, evals);
    std::printf("seamless::Interval : %8.2f Mevals/s (%.3f s)\n", evals / ts * 1e-6, ts);
    std::printf("Boost.Interval     : %8.2f Mevals/s (%.3f s)\n", evals / tb * 1e-6, tb);
    std::printf("Boost.Interval opp : %8.2f Mevals/s (%.3f s), guard held\n", evals / to * 1e-6,
                to);
    std::printf("ratio seamless/boost throughput: %.2f (per-op rounding), %.2f (opp + guard)\n",
                tb / ts, to / ts);
    std::printf("(checksum %g)\n", sink);
    return 0;
}
