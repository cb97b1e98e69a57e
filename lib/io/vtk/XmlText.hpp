#pragma once
// Internal to lib/io/vtk: what the hand-written XML files (.pvd collections, .pvtp masters) share.

#include <string>

namespace mfwave {

// `text` with the characters that would break an XML attribute value escaped.
std::string xmlEscaped(const std::string& text);

// `file` (a path as the caller opens it) relative to the folder of `anchor` (the file that will
// refer to it), with '/' separators, so an output folder can be moved or copied as a whole.
std::string relativeToFolderOf(const std::string& anchor, const std::string& file);

}  // namespace mfwave
