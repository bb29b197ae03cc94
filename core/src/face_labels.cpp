// Mesh face labels set one at a time: recorded inside an EditJournal step.
#include "sxk/mesh.hpp"
#include "undo_log.hpp"

namespace sxk {

namespace {

Simplex label_key(const Simplex& face) { return Simplex(+1, face.vertices()); }

}  // namespace

std::optional<int> Mesh::face_label(const Simplex& face) const {
    const auto it = m_face_labels.find(label_key(face));
    return it == m_face_labels.end() ? std::nullopt : std::optional<int>(it->second);
}

void Mesh::set_face_label(const Simplex& face, int label) {
    const Simplex key = label_key(face);
    if (m_undo != nullptr) m_undo->face_label(*this, key);
    ++m_revision;
    m_face_labels[key] = label;
}

bool Mesh::erase_face_label(const Simplex& face) {
    const Simplex key = label_key(face);
    const auto it = m_face_labels.find(key);
    if (it == m_face_labels.end()) return false;
    if (m_undo != nullptr) m_undo->face_label(*this, key);
    ++m_revision;
    m_face_labels.erase(it);
    return true;
}

}  // namespace sxk
