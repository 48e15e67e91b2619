// SPDX-License-Identifier: MIT
#include <seamless/tessellate/tessellation_stats_json.h>

#include <nlohmann/json.hpp>

namespace seamless {

std::string tessellation_stats_json(const TessellationStats& s, const StatsSource& source) {
    nlohmann::json js{
        {"model", source.model},
        {"output", source.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(source.output)},
        {"surfaces", s.surfaces},
        {"patches", s.patches},
        {"subpatches", s.subpatches},
        {"triangles", s.triangles},
        {"vertices", s.vertices},
        {"shared_edges", s.shared_edges},
        {"collapsed_edges", s.collapsed_edges},
        {"seams", s.seams},
        {"seam_vertices", s.seam_vertices},
        {"flipped_surfaces", s.flipped_surfaces},
        {"seam_tolerance", s.seam_tolerance},
        {"nonplanar_subpatches", s.nonplanar_subpatches},
        {"two_triangle_subpatches", s.two_triangle_subpatches},
        {"max_depth", s.max_depth},
        {"d_max", s.d_max},
        {"eps1", s.eps1},
        {"eps2", s.eps2},
        {"tolerance", s.tolerance},
        {"angle_degrees", source.angle_degrees},
        {"max_error_bound", s.max_error_bound},
        {"certified_bound", s.max_error_bound},
        {"above_tolerance", s.above_tolerance},
        {"passes", s.passes},
        {"seconds", s.seconds}};
    const PhaseSeconds& ph = s.phases;
    js["phase_seconds"] = {{"subdivision", ph.subdivision},
                           {"boundaries", ph.boundaries},
                           {"rings", ph.rings},
                           {"numbering", ph.numbering},
                           {"bounds", ph.bounds},
                           {"normals", ph.normals},
                           {"fans", ph.fans},
                           {"orientation", ph.orientation},
                           {"scaling", ph.scaling}};
    if (s.brep.faces > 0 || s.brep.faces_left_out > 0) { // a B-rep model (tessellate/trimmed/)
        const BRepStats& b = s.brep;
        js["brep"] = {{"faces", b.faces},
                      {"edges", b.edges},
                      {"edge_points", b.edge_points},
                      {"interior_points", b.interior_points},
                      {"resplit_rounds", b.resplit_rounds},
                      {"resplit_edges", b.resplit_edges},
                      {"face_runs", b.face_runs},
                      {"judged_triangles", b.judged_triangles},
                      {"faces_left_out", b.faces_left_out},
                      {"above_tolerance", b.above_tolerance},
                      {"angle", b.angle},
                      {"max_deviation", b.max_deviation},
                      {"certified", b.certified},
                      {"bound_triangles", b.bound_triangles},
                      {"bound_chords", b.bound_chords},
                      {"bound_seconds", b.bound_seconds},
                      {"edge_seconds", b.edge_seconds},
                      {"face_seconds", b.face_seconds},
                      {"mesh_seconds", b.mesh_seconds},
                      {"max_edge_tolerance", b.max_edge_tolerance},
                      {"max_edge_offset", b.max_edge_offset},
                      {"edges_above_tolerance", b.edges_above_tolerance},
                      {"warnings", b.warnings}};
    }
    return js.dump(2);
}

} // namespace seamless
