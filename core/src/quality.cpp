// Element quality measures (thesis §3.2.3) and the classification of degenerate tetrahedra.
#include "sxk/quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sxk/predicates.hpp"

namespace sxk {

namespace {

struct Vec {
    double x, y, z;
};
Vec operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(const Vec& a, const Vec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec scaled(const Vec& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
Vec plus(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

double max_edge(std::span<const Point> p) {
    double longest = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) longest = std::max(longest, norm(p[i] - p[j]));
    return longest;
}

double triangle_area(const Point& a, const Point& b, const Point& c) {
    return 0.5 * norm(cross(b - a, c - a));
}

// The vertices of the face opposite vertex i of a tetrahedron.
std::array<Point, 3> face_opposite(std::span<const Point> p, std::size_t i) {
    std::array<Point, 3> face;
    for (std::size_t j = 0, o = 0; j < 4; ++j)
        if (j != i) face[o++] = p[j];
    return face;
}

}  // namespace

double tetrahedron_volume(std::span<const Point> p) {
    return std::abs(dot(cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0])) / 6.0;
}

double element_volume(const Mesh& mesh, ElementId t, Positions positions) {
    // the corners in place, not element_points' vector: mean_element_volume runs over every
    // element when a snap cut begins (1.2M allocations on the large femur)
    std::array<Point, 4> corners{};
    const Simplex& s = mesh.simplex(t);
    for (int j = 0; j < 4; ++j)
        corners[static_cast<std::size_t>(j)] =
            positions == Positions::reference ? mesh.reference(s.vertex(j)) : mesh.deformed(s.vertex(j));
    return tetrahedron_volume(corners);
}

double mean_element_volume(const Mesh& mesh, Positions positions) {
    if (mesh.element_count() == 0) return 0;
    double sum = 0;
    for (const ElementId t : elements(mesh)) sum += element_volume(mesh, t, positions);
    return sum / double(mesh.element_count());
}

double aspect_ratio(std::span<const Point> p) {
    const double longest = max_edge(p);
    if (longest == 0) return 0;
    double min_height = std::numeric_limits<double>::infinity();
    if (p.size() == 4) {
        // height over face opposite i = 3 V / area(face)
        const double volume = tetrahedron_volume(p);
        for (std::size_t i = 0; i < 4; ++i) {
            const auto f = face_opposite(p, i);
            const double area = triangle_area(f[0], f[1], f[2]);
            min_height = std::min(min_height, area > 0 ? 3 * volume / area : 0.0);
        }
    } else {
        // height over edge opposite i = 2 A / length(edge)
        const double area = triangle_area(p[0], p[1], p[2]);
        for (std::size_t i = 0; i < 3; ++i) {
            const double edge = norm(p[(i + 1) % 3] - p[(i + 2) % 3]);
            min_height = std::min(min_height, edge > 0 ? 2 * area / edge : 0.0);
        }
    }
    return min_height / longest;
}

double relative_distance_to_hull(std::span<const Point> face, const Point& p) {
    const double longest = max_edge(face);
    if (!(longest > 0)) return std::numeric_limits<double>::infinity();
    const Vec w = p - face[0];
    const Vec u = face[1] - face[0];
    if (face.size() == 2) {  // to the line
        const double along = dot(w, u) / dot(u, u);
        return norm(Vec{w.x - along * u.x, w.y - along * u.y, w.z - along * u.z}) / longest;
    }
    const Vec n = cross(u, face[2] - face[0]);
    const double nn = dot(n, n);
    if (!(nn > 0)) return std::numeric_limits<double>::infinity();
    return std::abs(dot(w, n)) / std::sqrt(nn) / longest;
}

double radius_ratio(std::span<const Point> p) {
    if (p.size() == 4) {
        const double volume = tetrahedron_volume(p);
        if (volume == 0) return 0;
        double area = 0;
        for (std::size_t i = 0; i < 4; ++i) {
            const auto f = face_opposite(p, i);
            area += triangle_area(f[0], f[1], f[2]);
        }
        const double inradius = 3 * volume / area;
        const Vec a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
        const Vec numerator = plus(plus(scaled(cross(b, c), dot(a, a)), scaled(cross(c, a), dot(b, b))),
                                   scaled(cross(a, b), dot(c, c)));
        const double circumradius = norm(numerator) / (12 * volume);
        return 3 * inradius / circumradius;
    }
    const double a = norm(p[1] - p[2]), b = norm(p[0] - p[2]), c = norm(p[0] - p[1]);
    const double area = triangle_area(p[0], p[1], p[2]);
    if (area == 0) return 0;
    const double inradius = 2 * area / (a + b + c);
    const double circumradius = a * b * c / (4 * area);
    return 2 * inradius / circumradius;
}

std::array<double, 6> dihedral_angles(std::span<const Point> p) {
    // The faces at edge (i,j) are those opposite the two other vertices k and l; the interior
    // angle between them is pi minus the angle between their outward normals.
    static constexpr std::array<std::array<std::size_t, 4>, 6> edges{{
        {0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}}};
    std::array<Vec, 4> outward{};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto f = face_opposite(p, i);
        Vec n = cross(f[1] - f[0], f[2] - f[0]);
        if (dot(n, p[i] - f[0]) > 0) n = scaled(n, -1);
        outward[i] = n;
    }
    std::array<double, 6> angles{};
    for (std::size_t e = 0; e < 6; ++e) {
        const Vec& a = outward[edges[e][2]];
        const Vec& b = outward[edges[e][3]];
        // atan2 of |a x b| and a.b is accurate near 0 and pi, where acos is not
        const double between = std::atan2(norm(cross(a, b)), dot(a, b));
        angles[e] = (norm(a) == 0 || norm(b) == 0) ? 0.0 : pi - between;
    }
    return angles;
}

std::array<double, 3> triangle_angles(std::span<const Point> p) {
    std::array<double, 3> angles{};
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
        angles[i] = std::atan2(norm(cross(a, b)), dot(a, b));
    }
    return angles;
}

std::vector<Point> element_points(const Mesh& mesh, ElementId t, Positions positions) {
    std::vector<Point> points;
    points.reserve(4);
    for (VertexId v : mesh.simplex(t).vertices())
        points.push_back(positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v));
    return points;
}

std::string_view to_string(DegenerateClass c) {
    switch (c) {
        case DegenerateClass::none: return "none";
        case DegenerateClass::needle: return "needle";
        case DegenerateClass::spindle: return "spindle";
        case DegenerateClass::sliver: return "sliver";
        case DegenerateClass::cap: return "cap";
    }
    return "unknown";
}

DegenerateClass classify_tetrahedron(std::span<const Point> tetrahedron,
                                     const DegeneracyThresholds& thresholds) {
    if (aspect_ratio(tetrahedron) >= thresholds.aspect_ratio) return DegenerateClass::none;
    const auto angles = dihedral_angles(tetrahedron);
    const auto large = std::count_if(angles.begin(), angles.end(),
                                     [&](double a) { return a > thresholds.large_angle; });
    switch (large) {
        case 0: return DegenerateClass::needle;
        case 1: return DegenerateClass::spindle;
        case 2: return DegenerateClass::sliver;
        default: return DegenerateClass::cap;
    }
}

QualitySummary summarize_quality(const Mesh& mesh, const DegeneracyThresholds& thresholds,
                                 Positions positions) {
    QualitySummary q;
    q.min_aspect_ratio = q.min_radius_ratio = q.min_angle = std::numeric_limits<double>::infinity();
    double aspect_sum = 0, radius_sum = 0;
    std::array<Point, 4> points{};
    const bool tets = mesh.topological_dimension() == 3;
    for (ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        for (int j = 0; j < s.count(); ++j)
            points[static_cast<std::size_t>(j)] = positions == Positions::reference
                                                      ? mesh.reference(s.vertex(j))
                                                      : mesh.deformed(s.vertex(j));
        const std::span<const Point> p(points.data(), static_cast<std::size_t>(s.count()));
        ++q.elements;
        const double aspect = aspect_ratio(p);
        const double radius = radius_ratio(p);
        q.min_aspect_ratio = std::min(q.min_aspect_ratio, aspect);
        q.max_aspect_ratio = std::max(q.max_aspect_ratio, aspect);
        q.min_radius_ratio = std::min(q.min_radius_ratio, radius);
        aspect_sum += aspect;
        radius_sum += radius;
        ++q.aspect_histogram[std::min<std::size_t>(9, static_cast<std::size_t>(std::max(0.0, aspect) * 10))];
        if (tets) {
            for (double a : dihedral_angles(p)) {
                q.min_angle = std::min(q.min_angle, a);
                q.max_angle = std::max(q.max_angle, a);
            }
            const DegenerateClass c = classify_tetrahedron(p, thresholds);
            ++q.by_class[static_cast<std::size_t>(c)];
        } else {
            for (double a : triangle_angles(p)) {
                q.min_angle = std::min(q.min_angle, a);
                q.max_angle = std::max(q.max_angle, a);
            }
        }
        if (aspect < thresholds.aspect_ratio) ++q.degenerate;
        const Sign orientation = element_orientation(mesh, t, positions);
        if (orientation == Sign::negative) ++q.inverted;
        if (orientation == Sign::zero) ++q.flat;
    }
    if (q.elements == 0) {
        q.min_aspect_ratio = q.min_radius_ratio = q.min_angle = 0;
    } else {
        q.mean_aspect_ratio = aspect_sum / static_cast<double>(q.elements);
        q.mean_radius_ratio = radius_sum / static_cast<double>(q.elements);
    }
    return q;
}

std::size_t folded_neighbours(const Mesh& mesh, Positions positions) {
    if (mesh.topological_dimension() != 2 || mesh.ambient_dimension() != 3) return 0;
    auto corners = [&](ElementId t) {
        const Simplex& s = mesh.simplex(t);
        auto at = [&](int j) -> const Point& {
            return positions == Positions::deformed ? mesh.deformed(s.vertex(j)) : mesh.reference(s.vertex(j));
        };
        return s.sign() > 0 ? std::array<const Point*, 3>{&at(0), &at(1), &at(2)}
                            : std::array<const Point*, 3>{&at(0), &at(2), &at(1)};
    };
    std::size_t folds = 0;
    for (const ElementId t : elements(mesh))
        for (int i = 0; i < 3; ++i) {
            const ElementId n = mesh.neighbor(t, i);
            if (n == invalid_id || n < t) continue;  // each pair once
            const auto a = corners(t), b = corners(n);
            if (normal_alignment(*a[0], *a[1], *a[2], *b[0], *b[1], *b[2]) == Sign::negative) ++folds;
        }
    return folds;
}

}  // namespace sxk
