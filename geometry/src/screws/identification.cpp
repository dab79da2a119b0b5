// Gibson–Hunt type names (not templates; the identification itself is instantiated per scalar from
// identification_impl.hpp by soma_instantiate).
#include "soma/geometry/screws/identification.hpp"

namespace soma {

std::string screwSystemTypeName(ScrewSystemType t) {
  using T = ScrewSystemType;
  switch (t) {
    case T::Zero: return "0-system";
    case T::Line: return "line (p=0)";
    case T::Screw: return "screw";
    case T::Translation: return "translation (p=∞)";
    case T::IIC_2: return "IIC";
    case T::IB0sup_2: return "IB⁰";
    case T::IIA0_2: return "IIA(p=0)";
    case T::IIBp_2: return "IIB(p≠0)";
    case T::IIB0_2: return "IIB(p=0)";
    case T::IBp_2: return "IB(p≠0)";
    case T::IIAp_2: return "IIA(p≠0)";
    case T::IA_2: return "IA";
    case T::IID_3: return "IID";
    case T::IIA0_3: return "IIA(p=0)";
    case T::IIC0_3: return "IIC(p=0)";
    case T::IICp_3: return "IIC(p≠0)";
    case T::ICp_3: return "IC(p≠0)";
    case T::IC0_3: return "IC⁰";
    case T::IIB_3: return "IIB";
    case T::IB0_3: return "IB₀";
    case T::IB3_3: return "IB₃";
    case T::IIAp_3: return "IIA(p≠0)";
    case T::IA2_3: return "IA₂";
    case T::IA1_3: return "IA₁";
    case T::Whole: return "se(3)";
    case T::Unknown: return "unknown";
  }
  return "unknown";
}

int screwSystemTypeDimension(ScrewSystemType t) {
  using T = ScrewSystemType;
  switch (t) {
    case T::Zero: case T::Unknown: return 0;
    case T::Line: case T::Screw: case T::Translation: return 1;
    case T::IIC_2: case T::IB0sup_2: case T::IIA0_2: case T::IIBp_2: case T::IIB0_2:
    case T::IBp_2: case T::IIAp_2: case T::IA_2: return 2;
    case T::Whole: return 6;
    default: return 3;
  }
}

int screwSystemTypeParameterCount(ScrewSystemType t) {
  using T = ScrewSystemType;
  switch (t) {
    case T::Screw: case T::IIBp_2: case T::IBp_2: case T::IIAp_2: case T::IICp_3:
    case T::ICp_3: case T::IIB_3: case T::IIAp_3: return 1;
    case T::IA_2: case T::IB0_3: case T::IB3_3: case T::IA2_3: return 2;
    case T::IA1_3: return 3;
    default: return 0;
  }
}

}  // namespace soma
