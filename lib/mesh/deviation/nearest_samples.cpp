// SPDX-License-Identifier: MIT
// CGAL only here: a kd-tree of sample indices, the points read through a
// property map.
#include <seamless/mesh/deviation/nearest_samples.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <iterator>
#include <utility>

namespace seamless {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using PointMap = CGAL::Pointer_property_map<Point>::type;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<K>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
using KdTree = Search::Tree;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

} // namespace

struct NearestSamples::Tree {
    std::vector<Point> points;
    std::unique_ptr<KdTree> tree;
};

NearestSamples::NearestSamples(const std::vector<Vec3>& points) : tree_(std::make_unique<Tree>()) {
    tree_->points.reserve(points.size());
    for (const Vec3& p : points) tree_->points.emplace_back(p.x, p.y, p.z);
    std::vector<std::size_t> indices(points.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
    tree_->tree = std::make_unique<KdTree>(indices.begin(), indices.end(), KdTree::Splitter(),
                                           Traits(CGAL::make_property_map(tree_->points)));
    // Built before the queries: they may come from several threads.
    tree_->tree->build();
}

NearestSamples::~NearestSamples() = default;

void NearestSamples::nearest(Vec3 query, int k, std::vector<int>& out) const {
    out.clear();
    if (tree_->points.empty() || k <= 0) return;
    const Search search(*tree_->tree, Point(query.x, query.y, query.z), k, 0, true,
                        Search::Distance(CGAL::make_property_map(tree_->points)));
    std::vector<std::pair<double, std::size_t>> found;
    for (const auto& hit : search) found.emplace_back(hit.second, hit.first);
    std::sort(found.begin(), found.end());
    for (const auto& f : found) out.push_back(static_cast<int>(f.second));
}

void NearestSamples::within(Vec3 query, double radius, std::vector<int>& out) const {
    out.clear();
    if (tree_->points.empty() || !(radius >= 0)) return;
    std::vector<std::size_t> found;
    tree_->tree->search(std::back_inserter(found),
                        Sphere(Point(query.x, query.y, query.z), radius, 0,
                               Traits(CGAL::make_property_map(tree_->points))));
    std::sort(found.begin(), found.end());
    for (const std::size_t i : found) out.push_back(static_cast<int>(i));
}

} // namespace seamless
