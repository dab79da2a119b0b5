#pragma once
// The URDF text checked before TinyXML and urdfdom see it (issue 24): both recurse (TinyXML once
// per nested element, urdfdom's link tree once per link when it is destroyed), TinyXML 2.6.2 reads
// past the end of its buffer on a truncated UTF-8 sequence, and urdfdom links a joint graph with
// a cycle into a tree of shared pointers that never ends (a walk up from a link of the cycle never
// reaches the root, and the cycle is never freed). So, in one linear pass over the text:
//  * the text: at most limits::maxFileBytes, valid UTF-8 of XML characters only (no NUL, no
//    control character but tab, LF and CR, no U+FFFE/U+FFFF), no DOCTYPE, entity references only
//    the five of XML and numeric ones of XML characters; tags well formed and balanced;
//  * the size: elements nested at most limits::maxDepth deep, at most limits::maxXmlElements
//    elements, at most limits::maxJoints joints;
//  * the numbers: every numeric attribute URDF defines (origin xyz/rpy, axis xyz, limit, dynamics,
//    mass, inertia, geometry sizes, colours, mimic, calibration, safety controller) read by the one
//    number reader (number.hpp) in double, urdfdom's precision: hexadecimal, NaN, infinity and
//    out-of-range values are refused with the element and attribute named;
//  * the joint graph: every joint has a parent and a child link that exist and differ, no link is
//    the child of two joints, link and joint names are unique, exactly one link is no joint's child
//    (the root), and no link is its own ancestor (no cycle).
// Each defect is an InvalidInput "<origin>: not a valid URDF: line N: <defect>" (the text), "<origin>:
// not a valid URDF robot: <defect>" (the joint graph) or the number reader's "<origin>: joint "j" > limit@lower: …".
#include <string>

namespace soma::io::detail {

void checkUrdfText(const std::string& xml, const std::string& origin);

}  // namespace soma::io::detail
