#pragma once
// The SI quantities of the SRS as Boost.Units types, shared by the audit of the SRS's equations as
// written (dimensional_audit.cpp) and the audit of the model functions themselves (code_audit.cpp).

#include <boost/units/io.hpp>
#include <boost/units/quantity.hpp>
#include <boost/units/systems/si.hpp>
#include <string>
#include <type_traits>

namespace gp::verification::si_quantities {

namespace si = boost::units::si;
template <class Unit>
using Q = boost::units::quantity<Unit>;

// Quantities with the SI units the SRS declares. The radian is the coherent SI unit 1 (SI
// brochure, 9th ed.), so angles are dimensionless here, as Boost's plane_angle dimension is not.
using Dimensionless = Q<si::dimensionless>;
using Length = Q<si::length>;
using Time = Q<si::time>;
using Mass = Q<si::mass>;
using Velocity = Q<si::velocity>;
using Acceleration = Q<si::acceleration>;
using Force = Q<si::force>;
using Energy = Q<si::energy>;
using Angle = Dimensionless;
using AngularVelocity = decltype(Angle() / Time());
using AngularAcceleration = decltype(AngularVelocity() / Time());
using Torque = decltype(Length() * Force());
using Moment = decltype(Mass() * Length() * Length());
using Impulse = decltype(Force() * Time());
using GravitationalConstant = decltype(Length() * Length() * Length() / (Mass() * Time() * Time()));
template <class X>
using Rate = decltype(X() / Time());  // d/dt of X
template <class X>
using Squared = decltype(X() * X());
template <class X>
using Inverse = decltype(Dimensionless() / X());

template <class A, class B>
constexpr bool same_dimension =
    std::is_same_v<typename A::unit_type::dimension_type, typename B::unit_type::dimension_type>;

template <class X>
std::string dimension_of() {
  return boost::units::to_string(typename X::unit_type());
}

}  // namespace gp::verification::si_quantities
