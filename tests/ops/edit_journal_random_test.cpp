// Property test of EditJournal (issue 13, "Tests"): seeded random steps of 1-6 random local
// operations of the operation driver (flips, splits, collapses, dissections, bisections, Lawson
// flipping, node removal) mixed with checked vertex moves, element and face labels and attribute
// values, each step then committed, rolled back, undone or redone at random, on the four start
// meshes of the driver (planar grid, planar random points, octahedron surface, Kuhn cube).
//
// After every rollback and undo the mesh must be the snapshot of its checkpoint bit for bit
// (every slot, free list and neighbour, fuzz/ops_driver.hpp), every redo the snapshot after the
// step; validate() is clean; a MirrorWatcher, which applies each event to its own copy, agrees
// with the mesh (every net change told exactly once). Every 16th rollback also writes the mesh
// in each format before the step and after the rollback: the files are byte for byte equal.
// Two SpatialIndexes (sxk/locate.hpp), over the reference and over the deformed positions, watch
// throughout: after every step both validate (every live element and boundary face in its tree
// once, with the box its positions give now), and every 4th step they answer random locate,
// segment, triangle, nearest-boundary and ray queries as a scan of every element does
// (tests/core/locate_scan.hpp). The seed is printed; SXK_SEED=<n> replays a run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "core/fixtures.hpp"
#include "core/locate_scan.hpp"
#include "ops/random_steps.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/io.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

namespace fs = std::filesystem;
using test::random_move;
using ops_driver::Snapshot;
using ops_driver::snapshot;

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The mesh written in every format that holds it, as one string per file.
std::vector<std::string> files_of(const Mesh& mesh, const fs::path& dir) {
    std::vector<std::string> names{"m.mesh", "m.msh", "m.vtu", "m.node"};
    if (mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 3) names.push_back("m.off");
    std::vector<std::string> files;
    for (const std::string& name : names) {
        write_mesh(mesh, dir / name);
        files.push_back(bytes_of(dir / name));
        if (name == "m.node") files.push_back(bytes_of(dir / "m.ele"));
    }
    return files;
}

// Labels: an element label, or a face label on a boundary face.
void random_label(Mesh& mesh, std::mt19937_64& rng) {
    if (mesh.element_count() == 0) return;
    ElementId t = static_cast<ElementId>(rng() % mesh.element_capacity());
    while (!mesh.is_element(t)) t = static_cast<ElementId>((t + 1) % mesh.element_capacity());
    if (rng() % 2 == 0) {
        mesh.set_label(t, static_cast<int>(rng() % 4));
        return;
    }
    const int slot = static_cast<int>(rng() % static_cast<std::uint64_t>(mesh.element_vertex_count()));
    if (mesh.neighbor(t, slot) == invalid_id) mesh.set_face_label(mesh.simplex(t).subn(slot), 20 + static_cast<int>(rng() % 3));
}

struct Counts {
    int steps = 0, operations = 0, done = 0, commits = 0, rollbacks = 0, undos = 0, redos = 0, files = 0;
    int index_comparisons = 0;
};

void run(std::uint32_t kind, int steps, const char* name, Counts& counts) {
    const std::uint64_t seed = test::seed_for(name);
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    test::StartChoices start(rng, kind);
    ops_driver::Choices& choices = start.choices();
    const fs::path dir = fs::path(SXK_BINARY_DIR) / "test-ops-scratch" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    constexpr int restart = 500;  // steps per start mesh (dissections shred a mesh over time)
    for (int first = 0; first < steps; first += restart) {
        start.restart();
        Mesh mesh = ops_driver::start_mesh(choices, 6, 3);
        test::MirrorWatcher mirror;
        mesh.add_watcher(mirror);
        const SpatialIndex reference_index(mesh, Positions::reference);
        const SpatialIndex deformed_index(mesh, Positions::deformed);
        EditJournal journal(mesh);
        journal.set_history_limit(restart);
        // the snapshots before and after each step still in the history, newest last
        std::vector<std::pair<Snapshot, Snapshot>> history;
        std::vector<std::pair<Snapshot, Snapshot>> redo;
        for (int i = first; i < std::min(steps, first + restart); ++i) {
            ++counts.steps;
            const Snapshot before = snapshot(mesh);
            const bool compare_files = counts.rollbacks % 16 == 0;
            const std::vector<std::string> files = compare_files ? files_of(mesh, dir) : std::vector<std::string>{};
            journal.checkpoint();
            const int operations = 1 + static_cast<int>(rng() % 6);
            for (int o = 0; o < operations; ++o) {
                switch (rng() % 5) {
                    case 0: random_move(mesh, rng); break;
                    case 1: random_label(mesh, rng); break;
                    default: {
                        const ops_driver::Step op = ops_driver::run_step(mesh, choices, 600);
                        ++counts.operations;
                        counts.done += op.done;
                        ASSERT_TRUE(op.finding.empty()) << "step " << i << ": " << op.finding;
                    }
                }
                if (::testing::Test::HasFatalFailure()) return;
            }
            const std::uint64_t choice = rng() % 10;
            if (choice == 9 && !redo.empty()) {
                // redo right after an undo: this step's edits are rolled back first (a committed
                // step would clear what there is to redo), then the undone step comes back
                ASSERT_TRUE(journal.rollback().ok());
                ++counts.rollbacks;
                ASSERT_TRUE(snapshot(mesh) == before) << "step " << i << ": the rollback left another mesh";
                ASSERT_TRUE(journal.redo().ok()) << "step " << i;
                ++counts.redos;
                ASSERT_TRUE(snapshot(mesh) == redo.back().second) << "step " << i << ": redo";
                history.push_back(redo.back());
                redo.pop_back();
            } else if (choice < 4) {
                ASSERT_TRUE(journal.rollback().ok());
                ++counts.rollbacks;
                ASSERT_TRUE(snapshot(mesh) == before) << "step " << i << ": the rollback left another mesh";
                if (compare_files) {
                    ++counts.files;
                    ASSERT_EQ(files_of(mesh, dir), files) << "step " << i << ": the files differ after the rollback";
                }
            } else {
                ASSERT_TRUE(journal.commit().ok());
                ++counts.commits;
                if (journal.undo_count() == history.size() + 1) {  // a step that recorded nothing is none
                    history.emplace_back(before, snapshot(mesh));
                    redo.clear();
                }
                ASSERT_EQ(journal.undo_count(), history.size());
                if (choice == 8 && !history.empty()) {
                    ASSERT_TRUE(journal.undo().ok()) << "step " << i;
                    ++counts.undos;
                    ASSERT_TRUE(snapshot(mesh) == history.back().first) << "step " << i << ": undo";
                    redo.push_back(history.back());
                    history.pop_back();
                }
            }
            const auto valid = mesh.validate();
            ASSERT_TRUE(valid.ok()) << "step " << i << ": " << valid.reason();
            mirror.expect_mirrors(mesh);
            for (const SpatialIndex* index : {&reference_index, &deformed_index}) {
                const auto indexed = index->validate();
                ASSERT_TRUE(indexed.ok()) << "step " << i << ": " << indexed.reason();
                if (i % 4 == 0) test::expect_index_agrees(*index, rng, 2, "step " + std::to_string(i));
            }
            counts.index_comparisons += i % 4 == 0;
            if (::testing::Test::HasFailure()) FAIL() << "step " << i;
        }
        mesh.remove_watcher(mirror);
    }
}

// Runs `steps` steps on start meshes of `kind` and checks that every kind of ending happened.
void run_and_count(std::uint32_t kind, int steps, const char* name) {
    Counts c;
    run(kind, steps, name, c);
    std::cout << "[ done     ] steps " << c.steps << ", operations " << c.operations << " (" << c.done
              << " done), commits " << c.commits << ", rollbacks " << c.rollbacks << ", undos " << c.undos
              << ", redos " << c.redos << ", file comparisons " << c.files << ", index comparisons "
              << c.index_comparisons << "\n";
    EXPECT_GT(c.rollbacks, c.steps / 4);
    EXPECT_GT(c.undos, 0);
    EXPECT_GT(c.redos, 0);
    EXPECT_GT(c.files, 0);
    EXPECT_GT(c.index_comparisons, c.steps / 5);
}

TEST(EditJournalRandom, JitteredPlanarGrid) { run_and_count(0, 3000, "EditJournalRandom.JitteredPlanarGrid"); }
TEST(EditJournalRandom, PlanarRandomPoints) { run_and_count(1, 2000, "EditJournalRandom.PlanarRandomPoints"); }
TEST(EditJournalRandom, OctahedronSurface) { run_and_count(2, 2000, "EditJournalRandom.OctahedronSurface"); }
TEST(EditJournalRandom, JitteredKuhnCube) { run_and_count(3, 3000, "EditJournalRandom.JitteredKuhnCube"); }

}  // namespace
}  // namespace sxk
