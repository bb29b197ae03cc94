// A body from the elasticity plug-in's options (sxk/plugins/elasticity.hpp): what `sxk deform`
// and the service's simulate both set up, with the same messages. The words of the command line
// are read into the options by the command-line library (cli/body_words.hpp).
//
// Two stages: the options alone (check_body: their ranges, the selections, something holds the
// body), then on the mesh (build_body: the body, its constraints and loads; a selection that
// selects nothing is refused). Refusals are bad_argument and say what was
// wrong as `sxk deform` says it, without its "sxk: " ("deform: --fix 'x<9' selects no vertex of
// IN").
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "elastic_body.hpp"
#include "sxk/plugins/elasticity.hpp"

namespace sxk::elasticity {

struct BuiltBody {
    std::unique_ptr<ElasticBody> body;  // on the heap: a body attached as a watcher must not move
    std::size_t loaded = 0;             // vertices with a load
    bool planar = false;
    Model model = Model::linear;
};

Outcome<Done> check_body(const Options& options);

// The body of `mesh` (check_body first). `file` names the mesh's file in messages ("FILE:0: ..."); a caller without
// one (the service's simulate) passes "" and the messages say "the mesh", with no location that
// is not a file's.
Outcome<BuiltBody> build_body(const Mesh& mesh, const std::string& file, const Options& options);

}  // namespace sxk::elasticity
