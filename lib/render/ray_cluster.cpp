// SPDX-License-Identifier: MIT
#include <seamless/render/ray_cluster.h>

#include <seamless/interval/hansen_sengupta.h>

namespace seamless {

Box3 cluster_box(const RayCluster& c) {
    Box3 b;
    for (double q : {c.q.lo(), c.q.hi()}) {
        Vec3 lo, hi;
        for (int i = 0; i < 3; ++i) {
            const Interval p = c.origin[i] + Interval(q) * c.direction[i];
            lo[i] = p.lo();
            hi[i] = p.hi();
        }
        b.extend(lo);
        b.extend(hi);
    }
    return b;
}

bool may_hit_triangle(const RayCluster& c, Vec3 T1, Vec3 T2, Vec3 T3) {
    IMat<3> A;
    for (int i = 0; i < 3; ++i) {
        A(i, 0) = Interval(T2[i]) - Interval(T1[i]);
        A(i, 1) = Interval(T3[i]) - Interval(T1[i]);
        A(i, 2) = -c.direction[i];
    }
    const double qt = c.q.mid();
    IVec<3> b;
    for (int i = 0; i < 3; ++i)
        b[i] = Interval(T1[i]) - (c.origin[i] + Interval(qt) * c.direction[i]);
    IVec<3> x;
    x[0] = Interval(0.0, 1.0);
    x[1] = Interval(0.0, 1.0);
    x[2] = c.q - Interval(qt);
    for (int iter = 0; iter < 4; ++iter) {
        const RVec<3> w = mid(x);
        // F(w~) = b + A w~, enclosed; A is a Lipschitz matrix of the linear F.
        const IVec<3> Fw = b + A * to_ivec<3>(w);
        const HansenSenguptaStep<3> step = hansen_sengupta<3>(A, Fw, x, w);
        if (step.box.is_empty()) return false;
        IVec<3> y = step.box;
        // beta + delta <= 1
        if (y[0].lo() + y[1].lo() > 1.0) return false;
        const bool progress = y[0].width() < 0.9 * x[0].width() ||
                              y[1].width() < 0.9 * x[1].width() ||
                              y[2].width() < 0.9 * x[2].width();
        x = y;
        if (!progress) break;
    }
    return true;
}

} // namespace seamless
