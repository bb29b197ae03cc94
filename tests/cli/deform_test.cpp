// sxk deform IN OUT (the elasticity plug-in, thesis §3.1) through the binary: the thesis'
// cantilever solved from the command line, prescribed displacements written exactly, the JSON
// report, and every usage and input error with its exact message and exit code.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"
#include "two_bodies.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"

namespace sxk::test {
namespace {

struct DeformFixture {
    ScratchFolder folder;
    fs::path in = folder / "beam.mesh";
    fs::path out = folder / "out.mesh";
    // The thesis' coarsest beam (Table 3.1): 1.2 x 0.2 x 0.3 m in 16 x 4 x 4 Kuhn cells.
    DeformFixture() { write_mesh(*make_kuhn_box({16, 4, 4}, {1.2 / 16, 0.2 / 4, 0.3 / 4}), in); }
    ProcessResult run(std::vector<std::string> options) {
        std::vector<std::string> args{"deform", in.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        return sxk(args);
    }
};

const std::string deform_hint = "Run 'sxk deform --help' for more information.\n";

TEST(SxkDeform, HelpNamesEveryOption) {
    const ProcessResult run = sxk({"deform", "--help"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
    for (const char* word :
         {"IN", "OUT", "--fix", "--displace", "--force", "--material", "--E", "--nu", "--tol",
          "--max-iterations", "--json", "--strict", "--thickness", "--share", "--plot", "--gravity",
          "--density", "sxk deform"})
        EXPECT_NE(run.out.find(word), std::string::npos) << word << " missing from\n" << run.out;
}

TEST(SxkDeform, ListedAsAPluginCommand) {
    const ProcessResult run = sxk({"plugins"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_NE(run.out.find("elasticity 0.3.0  linear and neo-Hookean elasticity: matrix-free CG on "
                           "tetrahedra and plane-stress triangles; sxk deform\n"),
              std::string::npos)
        << run.out;
}

// The cantilever of Table 3.1 from the command line: the tip's mean deflection is the one the
// library's test finds on this mesh (23.13% below the analytic 8.64e-3 m), the clamped end does
// not move, and OUT holds the deformed positions.
TEST(SxkDeform, SolvesTheThesisCantilever) {
    DeformFixture f;
    const ProcessResult run = f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3,0", "--E", "1e6",
                                     "--nu", "0", "--tol", "1e-9", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["elements"], 1536);
    EXPECT_EQ(json["fixed"], 25);
    EXPECT_EQ(json["loaded"], 25);
    EXPECT_TRUE(json["converged"]);
    EXPECT_LE(json["residual"].get<double>(), json["threshold"].get<double>());
    EXPECT_EQ(json["history"].size(), json["iterations"].get<std::size_t>() + 1);
    const Mesh before = read_mesh(f.in), after = read_mesh(f.out);
    ASSERT_EQ(after.vertex_count(), before.vertex_count());
    double tip = 0;
    int tip_count = 0;
    for (VertexId v = 0; v < before.vertex_count(); ++v) {
        const Point& x = before.reference(v);
        const Point& y = after.reference(v);
        if (x[0] == 0) {
            EXPECT_EQ(x, y) << v;
        }
        if (x[0] > 1.1999) {
            tip += y[1] - x[1];
            ++tip_count;
        }
    }
    ASSERT_EQ(tip_count, 25);
    EXPECT_NEAR(-tip / tip_count, 8.64e-3 * (1 - 0.2313), 8.64e-3 * 1e-3);
}

// Prescribed displacements are written exactly; a free body between them is stretched.
TEST(SxkDeform, DisplacedVerticesLandExactly) {
    DeformFixture f;
    const ProcessResult run = f.run({"--fix", "x<0.001", "--displace", "x>1.1999:0.01,0,0"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find(" -> "), std::string::npos);
    EXPECT_NE(run.out.find("1536 tetrahedra, 50 vertices held, 0 loaded\n"), std::string::npos)
        << run.out;
    const Mesh before = read_mesh(f.in), after = read_mesh(f.out);
    for (VertexId v = 0; v < before.vertex_count(); ++v) {
        const Point& x = before.reference(v);
        if (x[0] > 1.1999) {
            EXPECT_EQ(after.reference(v), (Point{x[0] + 0.01, x[1], x[2]})) << v;
        } else if (x[0] > 0.5 && x[0] < 0.7) {
            EXPECT_GT(after.reference(v)[0], x[0]) << v;  // pulled along
        }
    }
}

TEST(SxkDeform, UsageErrorsSayWhat) {
    DeformFixture f;
    struct Case {
        std::vector<std::string> options;
        std::string err;
    };
    const std::string beam = f.in.string();
    const Case cases[] = {
        {{"--force", "x>1:0,-3,0"},
         "sxk: deform: nothing holds the body (no --fix or --displace), so it can move freely and "
         "the problem is "
         "singular; fix at least three non-collinear vertices of every connected part\n"},
        {{"--fix", "x<<1"},
         "sxk: deform: --fix: selector 'x<<1': term 'x<<1': expected a number after '<', found "
         "'<1'\n"},
        {{"--fix", "q<1"},
         "sxk: deform: --fix: selector 'q<1': term 'q<1': expected x, y or z compared with a "
         "number, label=N or "
         "boundary\n"},
        {{"--fix", "label=x"},
         "sxk: deform: --fix: selector 'label=x': term 'label=x': expected a whole number after "
         "'label=', found 'x'\n"},
        {{"--fix", "x<0&"},
         "sxk: deform: --fix: selector 'x<0&': term '': expected x, y or z compared with a number, "
         "label=N or boundary\n"},
        {{"--fix", "x<-1"}, "sxk: deform: --fix 'x<-1' selects no vertex of " + beam + "\n"},
        {{"--fix", "x<0.01", "--force", "x>1:0,1"},
         "sxk: deform: --force 'x>1:0,1': expected three numbers X,Y,Z after ':', found 2\n"},
        {{"--fix", "x<0.01", "--force", "x>1"},
         "sxk: deform: --force 'x>1': expected SELECTOR:X,Y,Z\n"},
        {{"--fix", "x<0.01", "--displace", "x>1:0,nan,0"},
         "sxk: deform: --displace 'x>1:0,nan,0': expected a finite number, found 'nan' in "
         "'0,nan,0'\n"},
        {{"--fix", "x<0.01", "--thickness", "0.1"},
         "sxk: deform: --thickness is for triangle meshes in the plane (plane stress); " + beam +
             " has 3-dimensional elements in 3-dimensional space\n"},
        {{"--fix", "x<0.01", "--plot", "convergence.svg"},
         "sxk: deform: --plot convergence.svg: the plot is a PNG picture; name it *.png\n"},
        {{"--fix", "x<0.01", "--force", "x>1.1999&y<0.0001&z<0.0001:0,-3,0", "--share", "area"},
         "sxk: deform: --force 'x>1.1999&y<0.0001&z<0.0001' --share area: no boundary face has all "
         "its corners among "
         "the selected vertices, so there is no area to share the force by\n"},
        {{"--fix", "x<0.01", "--gravity", "0,-9.8"},
         "sxk: deform: --gravity '0,-9.8': expected three numbers GX,GY,GZ, found 2\n"},
        {{"--fix", "x<0.01", "--material", "rubber"},
         "sxk: deform: --material: rubber not in {linear,neohookean}\n" + deform_hint},
        {{"--fix", "x<0.01", "--nu", "0.5"},
         "sxk: deform: --nu: '0.5' is not in (-1, 0.5)\n" + deform_hint},
        // the whole numbers go through command_line.hpp's check too (CLI11's own message once)
        {{"--fix", "x<0.01", "--max-iterations", "0"},
         "sxk: deform: --max-iterations: '0' is not a whole number in 1..100000000\n" + deform_hint},
        {{"--fix", "x<0.01", "--max-iterations", "nan"},
         "sxk: deform: --max-iterations: 'nan' is not a whole number in 1..100000000\n" + deform_hint},
    };
    for (const Case& c : cases) {
        const ProcessResult run = f.run(c.options);
        EXPECT_EQ(run.exit_code, 2) << c.err;
        EXPECT_EQ(run.err, c.err);
        EXPECT_EQ(run.out, "");
        EXPECT_FALSE(fs::exists(f.out)) << c.err;
    }
}

TEST(SxkDeform, RefusesSurfacesAndWritesNothingItCannotStandBehind) {
    DeformFixture f;
    const fs::path surface = f.folder / "surface.off";
    write_file(surface, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1\n3 0 1 2\n");
    ProcessResult run = sxk({"deform", surface.string(), f.out.string(), "--fix", "x<0.5"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + surface.string() +
                           ":0: elasticity: the mesh has 2-dimensional elements in 3-dimensional "
                           "space; the body needs "
                           "tetrahedra in space or triangles in the plane\n");

    // too few iterations: exit 1, no file
    run = f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3,0", "--max-iterations", "5"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err.rfind(
                  "sxk: " + f.in.string() + ":0: CG did not converge in 5 iterations (|r| = ", 0),
              0u)
        << run.err;
    EXPECT_NE(run.err.find("); nothing written\n"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(f.out));

    // a load that turns elements inside out: linear elasticity has no bound on the displacement,
    // and the result would not be a mesh any command accepts
    run = f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3e6,0"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(
        run.err.rfind(
            "sxk: " + f.in.string() + ":0: elasticity: the solution cannot be shown: element ", 0),
        0u)
        << run.err;
    EXPECT_NE(run.err.find(" would be inverted in the deformed positions; nothing written\n"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(f.out));
}

// A strip of 8 x 4 squares of right triangles, 4 x 2 m and 0.01 m thick, in plane stress, clamped
// at x = 0 and pulled by 3 N at x = 4, shared by boundary length (the ends of the loaded edge get
// half shares: a uniform traction). The far end stretches by a little less than the free strip's
// F l / (E h t): the clamp keeps the end from narrowing. (The library's test holds the strip on
// rollers, which give F l / (E h t) exactly; the CLI has no line constraint.)
TEST(SxkDeform, StretchesAPlanarStripInPlaneStress) {
    ScratchFolder folder;
    const fs::path in = folder / "strip.mesh", out = folder / "strip-out.mesh";
    Mesh strip(2, 2);
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 8; ++i)
            strip.add_vertex({0.5 * i, 0.5 * j, 0});
    std::vector<Simplex> triangles;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) {
            const VertexId a = VertexId(9 * j + i);
            triangles.emplace_back(+1, std::initializer_list<VertexId>{a, a + 1, a + 10});
            triangles.emplace_back(+1, std::initializer_list<VertexId>{a, a + 10, a + 9});
        }
    ASSERT_TRUE(strip.assign_elements(triangles).ok());
    write_mesh(strip, in);
    const ProcessResult run = sxk(
        {"deform",  in.string(),   out.string(), "--fix", "x=0&y=0", "--displace", "x=0&y>0:0,0,0",
         "--force", "x=4:3,0,0",   "--share",    "area",  "--E",     "1e5",        "--nu",
         "0.3",     "--thickness", "0.01",       "--tol", "1e-10",   "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["elements"], 64);
    EXPECT_EQ(json["thickness"], 0.01);
    EXPECT_EQ(json["share"], "area");
    const Mesh result = read_mesh(out);
    ASSERT_EQ(result.topological_dimension(), 2);
    // within 10% of the free strip's stretch, and below it
    const double expected = 3.0 / (2 * 0.01) / 1e5 * 4;
    double mean = 0;
    for (VertexId v = 8; v < 45; v += 9)
        mean += (result.reference(v)[0] - 4) / 5;
    EXPECT_GT(mean, 0.9 * expected);
    EXPECT_LT(mean, expected);
    EXPECT_TRUE(result.validate().ok());
}

// --material neohookean on the beam, and --plot: the picture is a PNG of the asked size class,
// written whether or not the solve converged.
TEST(SxkDeform, NeoHookeanAndTheConvergencePlot) {
    DeformFixture f;
    const fs::path plot = f.folder / "convergence.png";
    ProcessResult run =
        f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3,0", "--E", "1e6", "--nu", "0.3",
               "--material", "neohookean", "--tol", "1e-7", "--plot", plot.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["material"]["model"], "neohookean");
    EXPECT_TRUE(json["converged"].get<bool>());
    EXPECT_GT(json["evaluations"].get<int>(), json["iterations"].get<int>());
    ASSERT_TRUE(fs::exists(plot));
    const std::string png = slurp(plot);
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
    // the deflection is the linear one's within a percent: 3 N is a small load for this beam
    run = f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3,0", "--E", "1e6", "--nu", "0.3",
                 "--tol", "1e-7", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto linear = nlohmann::json::parse(run.out);
    const double a = json["largest_displacement"]["length"],
                 b = linear["largest_displacement"]["length"];
    EXPECT_NEAR(a, b, 0.01 * b);
    // not converged: the plot is still drawn, the mesh is not written
    fs::remove(plot);
    fs::remove(f.out);
    run = f.run({"--fix", "x<0.001", "--force", "x>1.1999:0,-3,0", "--max-iterations", "3",
                 "--plot", plot.string()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(fs::exists(plot));
    EXPECT_FALSE(fs::exists(f.out));
}

// Chapter 4's rod under its own weight from the command line (the library's
// ElasticityThesisRod test): the neo-Hookean tip sags less than the linear one and swings back
// towards the wall.
TEST(SxkDeform, ARodSagsUnderGravity) {
    ScratchFolder folder;
    const fs::path in = folder / "rod.mesh", out = folder / "rod-out.mesh";
    write_mesh(*make_kuhn_box({10, 6, 6}, {0.01, 0.01, 0.01}), in);
    auto tip = [&](const char* material) {
        const ProcessResult run =
            sxk({"deform", in.string(), out.string(), "--fix", "x=0", "--gravity", "0,-9.8,0",
                 "--density", "1000", "--E", "1e4", "--nu", "0.3", "--material", material, "--tol",
                 "1e-8", "--json"});
        EXPECT_EQ(run.exit_code, 0) << run.err;
        const auto json = nlohmann::json::parse(run.out);
        EXPECT_EQ(json["loaded"], 11 * 7 * 7);
        const Mesh result = read_mesh(out);
        Point mean{0, 0, 0};
        for (VertexId v = 0; v < result.vertex_count(); ++v)
            if (v % 11 == 10)  // x = l: make_kuhn_box numbers x fastest
                for (std::size_t k = 0; k < 3; ++k)
                    mean[k] += result.reference(v)[k] / 49;
        return mean;
    };
    const Point linear = tip("linear"), rubber = tip("neohookean");
    EXPECT_NEAR(linear[1] - 0.03, -0.0484, 0.0005);
    EXPECT_NEAR(rubber[1] - 0.03, -0.0469, 0.0005);
    EXPECT_LT(rubber[0], linear[0] - 0.005);
}


// Loads whose norm overflows a double (a load of 1e200 shared by the 81 vertices of the top is
// finite at each, |f| is not): the stop threshold was inf, and "CG: 0 iterations, |r| inf <= inf"
// passed for converged, exit 0, the input written back unchanged (issue 47). Refused, exit 1,
// nothing written, and --json still prints its object, converged false, with the refusal.
TEST(SxkDeform, LoadsWhoseNormOverflowsAreRefused) {
    ScratchFolder folder;
    const fs::path cube = folder / "cube8.mesh", out = folder / "d.mesh";
    ASSERT_EQ(sxk({"generate", cube.string(), "--cells", "8"}).exit_code, 0);
    const std::string too_large =
        "elasticity: the loads are too large: their norm overflows a double, so no residual can be measured "
        "against them; scale the loads, or the units, down";
    const std::vector<std::vector<std::string>> cases{
        {"--fix", "z<0.001", "--force", "z>7.99:0,0,1e200"},
        {"--fix", "z<0.001", "--force", "z>7.99:0,0,1e300"},
        {"--fix", "z<0.001", "--force", "z>7.99:0,0,1e200", "--material", "neohookean"},
        {"--fix", "z<0.001", "--gravity", "0,0,-9.8", "--density", "1e300"},
    };
    for (const auto& options : cases) {
        std::vector<std::string> args{"deform", cube.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        const ProcessResult run = sxk(args);
        EXPECT_EQ(run.exit_code, 1) << options[3];
        EXPECT_EQ(run.err, "sxk: " + cube.string() + ":0: " + too_large + "; nothing written\n") << options[3];
        EXPECT_EQ(run.out, "");
        EXPECT_FALSE(fs::exists(out));
        args.push_back("--json");
        const ProcessResult json_run = sxk(args);
        EXPECT_EQ(json_run.exit_code, 1);
        const auto json = nlohmann::json::parse(json_run.out);
        EXPECT_EQ(json["converged"], false);
        EXPECT_FALSE(json.contains("residual"));
        EXPECT_EQ(json["refusal"]["code"], "bad_argument");
        EXPECT_EQ(json["refusal"]["reason"], too_large);
        EXPECT_FALSE(fs::exists(out));
    }
    // displacements too large for doubles: K u overflows, the residual is not finite
    const ProcessResult displaced = sxk({"deform", cube.string(), out.string(), "--fix", "z<0.001", "--displace",
                                         "z>7.99:0,0,1e300", "--json"});
    EXPECT_EQ(displaced.exit_code, 1);
    const std::string not_finite =
        "elasticity: the residual is not finite after 0 iterations (|r| = inf, needed inf): the loads or the "
        "prescribed displacements are too large for double precision; scale them, or the units, down";
    EXPECT_EQ(displaced.err, "sxk: " + cube.string() + ":0: " + not_finite + "; nothing written\n");
    EXPECT_EQ(nlohmann::json::parse(displaced.out)["refusal"]["reason"], not_finite);
    EXPECT_FALSE(fs::exists(out));
}

// A component that carries a load and has no held vertex has no equilibrium: CG once chased it
// to |r| = 2.3e18 (issue 47). It is named before any solve, as the body with nothing holding it is.
TEST(SxkDeform, ALoadedBodyThatNothingHoldsIsNamed) {
    ScratchFolder folder;
    const fs::path two = folder / "two.mesh", out = folder / "d.mesh";
    write_two_cubes(two, {20, 0, 0});
    const ProcessResult run = sxk({"deform", two.string(), out.string(), "--fix", "x<0.001", "--force",
                                   "z>7.99:0,0,-1"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: deform: component 1 of " + two.string() +
                           " (3072 elements, as `sxk components` numbers them) is loaded and nothing holds it (no "
                           "--fix or --displace selects a vertex of it), so it can move freely and the problem is "
                           "singular; fix at least three non-collinear vertices of every connected part\n");
    EXPECT_FALSE(fs::exists(out));
    // held on both, or loaded only where held: solved
    EXPECT_EQ(sxk({"deform", two.string(), out.string(), "--fix", "z<0.001", "--force", "z>7.99:0,0,-1"}).exit_code,
              0);
    EXPECT_EQ(sxk({"deform", two.string(), out.string(), "--fix", "x<0.001", "--force", "x<8.01&z>7.99:0,0,-1"})
                  .exit_code,
              0);
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
}

}  // namespace
}  // namespace sxk::test
