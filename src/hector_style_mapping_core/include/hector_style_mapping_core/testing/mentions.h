#ifndef HECTOR_STYLE_MAPPING_CORE_TESTING_MENTIONS_H
#define HECTOR_STYLE_MAPPING_CORE_TESTING_MENTIONS_H

// The tests' check on error messages: does the text name the field, index or value it should.
#include <string>

namespace hector_style_mapping {
namespace testing {

inline bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace testing
}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_TESTING_MENTIONS_H
