// split_face (thesis §3.2 subdivision; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/split_face.hpp"

#include "ops/split_parents.hpp"

namespace sxk {

Outcome<SplitResult> split_face(Mesh& mesh, FaceId f, std::array<double, 3> weights, const SplitOptions& options) {
    if (mesh.topological_dimension() != 3)
        return Refusal{
            RefusalCode::wrong_dimension,
            "split_face: needs a tetrahedral mesh (split a triangle mesh's edges with split_edge)"};
    if (!mesh.is_face(f))
        return Refusal{RefusalCode::not_found,
                       "split_face: " + std::to_string(f) + " is not a face"};
    if (!detail::weights_inside(weights))
        return Refusal{RefusalCode::bad_argument,
                       "split_face: the weights must all be > 0 (the new vertex inside the face)"};
    const double sum = weights[0] + weights[1] + weights[2];
    for (double& w : weights) w /= sum;

    const Simplex sigma = mesh.face_simplex(f);
    std::vector<ElementId> parents{mesh.face_element(f)};
    if (mesh.mate(f) != invalid_id) parents.push_back(mesh.face_element(mesh.mate(f)));

    return detail::split_parents(mesh, parents, sigma.vertices(), weights, "split_face", options.vanishing_with);
}

}  // namespace sxk
