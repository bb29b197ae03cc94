// The needle's frame (needle_frame.hpp).
#include "needle_frame.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace sxk::needle {

Frame::Frame(const Needle& needle) : tip(vec(needle.tip)) {
    const Eigen::Vector3d shaft = tip - vec(needle.base);
    length = shaft.norm();
    axis = length > 0 ? Eigen::Vector3d(shaft / length) : Eigen::Vector3d::UnitX();
}

Point Frame::perp(const Point& x) const {
    const Eigen::Vector3d d = vec(x) - tip;
    return point(d - d.dot(axis) * axis);
}

Point Frame::place(double along_axis, const Point& offset) const {
    return point(tip + along_axis * axis + vec(offset));
}

Point turned(const Point& perp, const Frame& from, const Frame& to) {
    Eigen::Vector3d offset = vec(perp);
    if (from.axis.dot(to.axis) > -1 + 1e-12)
        offset = Eigen::Quaterniond::FromTwoVectors(from.axis, to.axis) * offset;
    offset -= offset.dot(to.axis) * to.axis;
    return point(offset);
}

}  // namespace sxk::needle
