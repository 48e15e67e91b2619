// SPDX-License-Identifier: MIT
// The k points of a fixed set nearest to a query point, or those within a
// radius of it: CGAL's kd-tree (kept inside nearest_samples.cpp), built
// once, then queried from any number of threads at once.
#pragma once

#include <seamless/base/vec.h>

#include <memory>
#include <vector>

namespace seamless {

class NearestSamples {
  public:
    explicit NearestSamples(const std::vector<Vec3>& points);
    ~NearestSamples();
    NearestSamples(const NearestSamples&) = delete;
    NearestSamples& operator=(const NearestSamples&) = delete;

    // Indices of the min(k, size) nearest points into `out`, nearest first
    // (ties in index order: the result does not depend on the thread).
    void nearest(Vec3 query, int k, std::vector<int>& out) const;
    // Indices of the points within `radius` of the query into `out`, in
    // index order.
    void within(Vec3 query, double radius, std::vector<int>& out) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

} // namespace seamless
