// The elasticity service's simulation (elasticity_service.hpp): a body from `sxk deform`'s
// options, attached to its mesh, relaxed a bounded number of CG iterations per call.
#include <algorithm>
#include <chrono>
#include <sstream>

#include "body_setup.hpp"
#include "command_line.hpp"
#include "elasticity_service.hpp"
#include "simulation.hpp"
#include "solve.hpp"

namespace sxk::elasticity {

namespace {

class BodySimulation final : public Simulation {
public:
    BodySimulation(Mesh& mesh, BuiltBody built, const SolveOptions& options)
        : m_mesh(mesh), m_built(std::move(built)), m_options(options) {
        m_mesh.add_watcher(*m_built.body);
    }
    ~BodySimulation() override { m_mesh.remove_watcher(*m_built.body); }
    BodySimulation(const BodySimulation&) = delete;
    BodySimulation& operator=(const BodySimulation&) = delete;

    Outcome<RelaxReport> relax(std::size_t iterations) override {
        const auto start = std::chrono::steady_clock::now();
        // at most `iterations`, and never more than the options' --max-iterations
        SolveOptions options = m_options;
        options.max_iterations = std::min(iterations, m_options.max_iterations);
        iterations = options.max_iterations;
        // a fresh relaxation each call: its residual starts from the current displacements (the
        // warm start), and the body has heard the edits since the last call (refresh)
        RelaxReport result;
        auto run = [&](auto relaxation) -> Outcome<Done> {
            if (!relaxation) return relaxation.refusal();
            relaxation->run(iterations);
            const SolveReport report = relaxation->report();
            result.iterations = report.iterations;
            result.converged = report.converged;
            result.residual = report.residual;
            result.threshold = report.threshold;
            return Done{};
        };
        ElasticBody& body = *m_built.body;
        const Outcome<Done> ran = m_built.model == Model::linear ? run(LinearRelaxation::start(body, options))
                                                                 : run(NonlinearRelaxation::start(body, options));
        if (!ran) return ran.refusal().prefixed("relax: ");
        m_total += result.iterations;
        result.shown = body.write_deformed(m_mesh).ok();
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
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

private:
    Mesh& m_mesh;
    BuiltBody m_built;
    SolveOptions m_options;
    std::size_t m_total = 0;
};

}  // namespace

Outcome<std::unique_ptr<Simulation>> simulate(Mesh& mesh, std::span<const std::string> words) {
    BodySetup setup;
    CLI::App app("elasticity simulation", "deform");
    add_body_options(app, setup);
    std::vector<std::string> arguments(words.rbegin(), words.rend());  // CLI11 parses from the back
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& error) {
        return Refusal{RefusalCode::bad_argument, std::string("deform: ") + error.what()};
    }
    // the command's messages, without its "sxk: " and line end
    std::ostringstream messages;
    auto refused = [&messages] {
        std::string text = messages.str();
        if (text.rfind("sxk: ", 0) == 0) text.erase(0, 5);
        while (!text.empty() && text.back() == '\n') text.pop_back();
        return Refusal{RefusalCode::bad_argument, text};
    };
    const std::optional<ParsedBody> parsed = parse_body_setup(setup, messages);
    if (!parsed) return refused();
    std::optional<BuiltBody> built = build_body(mesh, "the mesh", setup, *parsed, messages);
    if (!built) return refused();
    const SolveOptions options{.tolerance = setup.tolerance,
                               .max_iterations = setup.max_iterations,
                               .stop = setup.stop == "external" ? StopCriterion::external_force
                                                                : StopCriterion::with_reactions};
    return std::unique_ptr<Simulation>(std::make_unique<BodySimulation>(mesh, std::move(*built), options));
}

}  // namespace sxk::elasticity
