// The elasticity service's simulation (sxk/plugins/elasticity.hpp): a body from `sxk deform`'s
// options, attached to its mesh, relaxed a bounded number of CG iterations per call.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <utility>

#include "body_setup.hpp"
#include "local_relaxation.hpp"
#include "simulation.hpp"
#include "solve.hpp"

namespace sxk::elasticity {

namespace {

class BodySimulation final : public Simulation {
public:
    BodySimulation(Mesh& mesh, BuiltBody built, const SolveOptions& options)
        : m_mesh(mesh), m_built(std::move(built)), m_options(options) {
        const ElasticBody& body = *m_built.body;
        m_held_by_options.resize(body.vertex_count());
        for (VertexId v = 0; v < body.vertex_count(); ++v)
            m_held_by_options[v] = body.freedom(v) != Freedom::free;
        m_mesh.add_watcher(*m_built.body);
    }
    ~BodySimulation() override { m_mesh.remove_watcher(*m_built.body); }
    // Setup's share of the first steps: the body's rest shapes, the local solvers' scratch.
    Outcome<Done> prepare() {
        if (Outcome<Done> fresh = m_built.body->refresh(); !fresh) return fresh;
        m_near.reserve(*m_built.body);
        m_far.reserve(*m_built.body);
        return Done{};
    }
    BodySimulation(const BodySimulation&) = delete;
    BodySimulation& operator=(const BodySimulation&) = delete;

    Outcome<RelaxReport> relax(std::size_t iterations) override {
        const auto start = std::chrono::steady_clock::now();
        const SolveOptions options = bounded(iterations);
        iterations = options.max_iterations;
        // a fresh relaxation each call: its residual starts from the current displacements (the
        // warm start), and the body has heard the edits since the last call (refresh)
        RelaxReport result;
        auto run = [&](auto relaxation) -> Outcome<Done> {
            if (!relaxation) return relaxation.refusal();
            relaxation->run(iterations);
            const SolveReport solved = relaxation->report();
            if (auto finite = detail::check_finite(solved); !finite) return finite;  // nothing to show
            result = report_of(solved);
            return Done{};
        };
        ElasticBody& body = *m_built.body;
        const Outcome<Done> ran = m_built.model == Model::linear ? run(LinearRelaxation::start(body, options))
                                                                 : run(NonlinearRelaxation::start(body, options));
        if (!ran) return ran.refusal().prefixed("relax: ");
        m_total += result.iterations;
        show(result, body.write_deformed(m_mesh));
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
    }

    Outcome<RelaxReport> relax_near(std::span<const VertexId> seeds, std::size_t iterations,
                                    std::size_t max_vertices) override {
        if (m_built.model != Model::linear) return relax(iterations);
        auto relaxed = relax_region(m_near, seeds, iterations, max_vertices);
        if (!relaxed) return relaxed.refusal().prefixed("relax_near: ");
        // the tolerance per vertex of what the far field may keep out of balance
        if (relaxed->region_vertices > 0)
            m_balance = relaxed->threshold / std::sqrt(static_cast<double>(relaxed->region_vertices));
        return relaxed;
    }

    Outcome<RelaxReport> relax_far(std::size_t iterations, std::size_t max_vertices) override {
        if (m_built.model != Model::linear) return RelaxReport{.converged = true};
        // the remembered rim vertex most out of balance now (the remembered value may be stale:
        // taken again before it counts)
        while (!m_frontier.empty()) {
            std::pop_heap(m_frontier.begin(), m_frontier.end());
            const VertexId v = m_frontier.back().second;
            m_frontier.pop_back();
            const VertexId one[] = {v};
            auto balance = out_of_balance(one);
            if (!balance) return balance.refusal().prefixed("relax_far: ");
            if (!((*balance)[0] > m_balance)) continue;
            auto relaxed = relax_region(m_far, one, iterations, max_vertices);
            if (!relaxed) return relaxed.refusal().prefixed("relax_far: ");
            return relaxed;
        }
        return RelaxReport{.converged = true};
    }

    void follow_far_field(bool follow) override {
        m_follow_far_field = follow;
        if (!follow) m_frontier.clear();
    }

    Outcome<bool> hold_piece(std::span<const ElementId> piece) override {
        ElasticBody& body = *m_built.body;
        if (Outcome<Done> fresh = body.refresh(); !fresh) return fresh.refusal().prefixed("hold_piece: ");
        FaceId lowest = invalid_id;
        for (const ElementId t : piece) {
            if (!m_mesh.is_element(t)) continue;
            for (const VertexId v : m_mesh.simplex(t).vertices())
                if (v < body.vertex_count() && body.freedom(v) != Freedom::free) return false;
            for (const FaceId f : m_mesh.faces(t))
                if (m_mesh.mate(f) == invalid_id && (lowest == invalid_id || f < lowest)) lowest = f;
        }
        if (lowest == invalid_id) return false;
        const Simplex face = m_mesh.face_simplex(lowest);  // by value: a range over a temporary's span dangles
        for (const VertexId v : face.vertices())
            if (Outcome<Done> fixed = body.fix(v, body.displacement(v)); !fixed)
                return fixed.refusal().prefixed("hold_piece: ");
        return true;
    }

    std::size_t total_iterations() const override { return m_total; }

    Outcome<Done> hold(VertexId v, Vector3 displacement) override {
        if (auto mine = tools_vertex(v, "hold"); !mine) return mine;
        return m_built.body->fix(v, displacement);
    }
    Outcome<Done> hold_on_line(VertexId v, Vector3 direction, Vector3 displacement) override {
        if (auto mine = tools_vertex(v, "hold_on_line"); !mine) return mine;
        return m_built.body->constrain_to_line(v, direction, displacement);
    }
    Outcome<Done> release(VertexId v) override {
        if (auto mine = tools_vertex(v, "release"); !mine) return mine;
        return m_built.body->free(v);
    }
    Outcome<Done> set_tool_force(VertexId v, Vector3 force) override {
        if (auto fresh = m_built.body->refresh_shapes(); !fresh) return fresh.refusal().prefixed("set_tool_force: ");
        Vector3& was = m_tool_force[v];
        const Vector3 change{force[0] - was[0], force[1] - was[1], force[2] - was[2]};
        if (auto added = m_built.body->add_force(v, change); !added) {
            if (was == Vector3{0, 0, 0}) m_tool_force.erase(v);
            return added.refusal().prefixed("set_tool_force: ");
        }
        was = force;
        if (force == Vector3{0, 0, 0}) m_tool_force.erase(v);
        return Done{};
    }
    Outcome<std::vector<VertexForces>> forces_at(std::span<const VertexId> vertices) override {
        ElasticBody& body = *m_built.body;
        // over the vertices' stars only: a tool asks every step
        if (auto fresh = body.refresh_shapes(); !fresh) return fresh.refusal().prefixed("forces_at: ");
        if (!body.elastic_forces_at(vertices, m_gradient))
            return Refusal{RefusalCode::would_invert, "forces_at: the displacements invert an element"};
        std::vector<VertexForces> forces(vertices.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const VertexId v = vertices[i];
            if (v >= body.vertex_count()) continue;
            for (int k = 0; k < 3; ++k) forces[i].elastic[k] = -m_gradient[i][k];
            forces[i].loaded = body.force(v);
        }
        return forces;
    }
    Vector3 displacement(VertexId v) const override {
        return v < m_built.body->vertex_count() ? m_built.body->displacement(v) : Vector3{0, 0, 0};
    }
    Outcome<Done> displacements_from_mesh() override {
        ElasticBody& body = *m_built.body;
        if (auto fresh = body.refresh(); !fresh) return fresh.refusal().prefixed("displacements_from_mesh: ");
        auto u = body.displacements();
        for (VertexId v = 0; v < body.vertex_count(); ++v) {
            if (m_mesh.vertex_element(v) == invalid_id) continue;
            const Point& reference = m_mesh.reference(v);
            const Point& deformed = m_mesh.deformed(v);
            for (int k = 0; k < 3; ++k) u[3 * v + k] = deformed[k] - reference[k];
        }
        // tool forces on vertices the mesh no longer has went with them
        std::erase_if(m_tool_force, [&](const auto& entry) { return entry.first >= body.vertex_count(); });
        return Done{};
    }

private:
    // The options with at most `iterations`, and never more than the options' --max-iterations.
    SolveOptions bounded(std::size_t iterations) const {
        SolveOptions options = m_options;
        options.max_iterations = std::min(iterations, m_options.max_iterations);
        return options;
    }
    // Whether write_deformed showed the solution, and why not.
    static void show(RelaxReport& report, const Outcome<Done>& written) {
        report.shown = written.ok();
        if (!written) report.not_shown = written.refusal();
    }
    // What a relax call reports of a solve (its time and what it wrote: the caller's).
    static RelaxReport report_of(const SolveReport& solve) {
        RelaxReport report;
        report.iterations = solve.iterations;
        report.converged = solve.converged;
        report.residual = solve.residual;
        report.threshold = solve.threshold;
        return report;
    }

    // The local solve around `seeds`, its region written, its rim remembered for relax_far.
    Outcome<RelaxReport> relax_region(LocalRelaxation& solver, std::span<const VertexId> seeds,
                                      std::size_t iterations, std::size_t max_vertices) {
        const auto start = std::chrono::steady_clock::now();
        ElasticBody& body = *m_built.body;
        auto local = solver.solve(body, seeds, max_vertices, bounded(iterations));
        if (!local) return local.refusal();
        RelaxReport result = report_of(local->solve);
        result.region_vertices = local->region_vertices;
        result.region_elements = local->elements;
        m_total += result.iterations;
        show(result, body.write_deformed(m_mesh, solver.region()));
        // the rim held the region: remember where it is out of balance, for relax_far
        if (m_follow_far_field) {
            if (Outcome<Done> kept = remember_rim(solver.rim(), max_vertices); !kept) return kept.refusal();
        }
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
    }

    // A local solve's rim vertices out of balance, into relax_far's heap.
    Outcome<Done> remember_rim(std::span<const VertexId> rim, std::size_t max_vertices) {
        auto balance = out_of_balance(rim);
        if (!balance) return balance.refusal();
        for (std::size_t i = 0; i < rim.size(); ++i)
            if ((*balance)[i] > m_balance) {
                m_frontier.emplace_back((*balance)[i], rim[i]);
                std::push_heap(m_frontier.begin(), m_frontier.end());
            }
        if (m_frontier.size() > 16 * max_vertices + 64) {  // keep the worst half: bounded memory
            const auto half = m_frontier.begin() + static_cast<std::ptrdiff_t>(m_frontier.size() / 2);
            std::nth_element(m_frontier.begin(), half, m_frontier.end(), std::greater<>());
            m_frontier.erase(half, m_frontier.end());
            std::make_heap(m_frontier.begin(), m_frontier.end());
        }
        return Done{};
    }

    // |P(f - K u)| at each of `vertices` (0 for a vertex not in the body), from their stars
    Outcome<std::vector<double>> out_of_balance(std::span<const VertexId> vertices) {
        ElasticBody& body = *m_built.body;
        if (!body.elastic_forces_at(vertices, m_gradient))
            return Refusal{RefusalCode::would_invert, "the displacements invert an element"};
        std::vector<double> norms(vertices.size(), 0.0);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const VertexId v = vertices[i];
            if (v >= body.vertex_count()) continue;
            const Vector3 f = body.force(v);
            Eigen::Vector3d r(f[0] - m_gradient[i][0], f[1] - m_gradient[i][1], f[2] - m_gradient[i][2]);
            body.project_vertex(v, r);
            norms[i] = r.norm();
        }
        return norms;
    }

    // v is a vertex of the body the options do not hold
    Outcome<Done> tools_vertex(VertexId v, const char* what) const {
        if (v < m_held_by_options.size() && m_held_by_options[v])
            return Refusal{RefusalCode::bad_argument, std::string(what) + ": vertex " + std::to_string(v) +
                                                          " is held by the body's options",
                           v};
        return Done{};
    }

    Mesh& m_mesh;
    BuiltBody m_built;
    SolveOptions m_options;
    std::size_t m_total = 0;
    std::vector<char> m_held_by_options;  // per vertex of the mesh as built: --fix or --displace
    std::map<VertexId, Vector3> m_tool_force;
    std::vector<Vector3> m_gradient;  // forces_at's scratch
    // relax_near's and relax_far's, kept between calls: apart, so that a far-field block between two
    // steps leaves the near region and its rows of K to the next step (LocalRelaxation::solve)
    LocalRelaxation m_near, m_far;
    // relax_far's: rim vertices and how far out of balance they were (a max-heap), and the
    // tolerance per vertex
    std::vector<std::pair<double, VertexId>> m_frontier;
    double m_balance = 0;
    bool m_follow_far_field = true;  // follow_far_field
};

}  // namespace

Outcome<std::unique_ptr<Simulation>> simulate(Mesh& mesh, const Options& body) {
    Outcome<BuiltBody> built = build_body(mesh, "", body);
    if (!built) return built.refusal();
    const SolveOptions options{.tolerance = body.tolerance,
                               .max_iterations = body.max_iterations,
                               .stop = body.stop == Stop::external ? StopCriterion::external_force
                                                                   : StopCriterion::with_reactions,
                               .rounding = body.rounding};
    auto simulation = std::make_unique<BodySimulation>(mesh, std::move(*built), options);
    // attached, the body heard init() and would compute every rest shape again at the first
    // solve: here, at setup, rather than inside a tool's first step (47 ms on a million triangles)
    if (Outcome<Done> prepared = simulation->prepare(); !prepared) return prepared.refusal();
    return std::unique_ptr<Simulation>(std::move(simulation));
}

}  // namespace sxk::elasticity
