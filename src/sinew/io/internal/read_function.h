// Reading OpenSim Function elements into sinew::Function objects.
#pragma once

#include <sinew/functions/function.h>
#include <sinew/io/internal/xml_document.h>

#include <pugixml.hpp>
#include <string>

namespace sinew::io::internal {

/// Reads one Function element; its tag is the OpenSim class name (<SimmSpline>, <Constant>,
/// <LinearFunction>, <MultiplierFunction>, ...). NaturalCubicSpline and natCubicSpline are read
/// as SimmSpline, as OpenSim renames them.
/// Throws sinew::Error (file, line, `component`) for an unknown type or malformed values.
functions::FunctionPtr ReadFunction(const XmlDocument& doc, const pugi::xml_node& element,
                                    const std::string& component);

/// Reads a function-valued property. `property` is either a wrapper (3.x
/// `<function><SimmSpline>...</SimmSpline></function>`) or, in 4.x, the Function element
/// itself (`<SimmSpline name="function">`). Returns nullptr for an empty wrapper.
functions::FunctionPtr ReadFunctionProperty(const XmlDocument& doc, const pugi::xml_node& property,
                                            const std::string& component);

/// Finds the function-valued property named `property` among the children of `parent`: a child
/// element <property> (the wrapper form, 3.x and some 4.x files) or a child Function element
/// whose name attribute is `property` (4.x inline form, e.g. <SimmSpline name="function"> or
/// <SimmSpline name="active_force_length_curve">). Returns an empty node when absent.
pugi::xml_node FindFunctionProperty(const pugi::xml_node& parent, const std::string& property);

/// FindFunctionProperty + ReadFunctionProperty: the function, or nullptr when the property is
/// absent or an empty wrapper.
functions::FunctionPtr ReadFunctionProperty(const XmlDocument& doc, const pugi::xml_node& parent,
                                            const std::string& property,
                                            const std::string& component);

/// True when `tag` names a Function class ReadFunction knows.
bool IsFunctionType(const std::string& tag);

}  // namespace sinew::io::internal
