#include "twin/Precision.h"

namespace twin {

const char* to_string(Precision p) {
  return p == Precision::exact ? "double" : p == Precision::single ? "float" : "half";
}

bool parse_precision(const std::string& text, Precision& out) {
  if (text == "double") out = Precision::exact;
  else if (text == "float") out = Precision::single;
  else if (text == "half") out = Precision::half;
  else return false;
  return true;
}

}  // namespace twin
