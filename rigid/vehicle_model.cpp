// The vehicle model and its two builders (Chapter II, Chapter III); see
// vehicle_model.h and docs/theory/rigid.md, sections 1a, 2 and 10.
#include "rigid/vehicle_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/plow_linkage.h"

namespace framedyn::rigid {

namespace {

constexpr int X = 0, Y = 1, Z = 2;

Eigen::Vector3d in_3d(const Eigen::Vector2d& p) { return {p.x(), 0.0, p.y()}; }

int index_of(const std::vector<std::string>& names, const std::string& n) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == n) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> coordinate_names_2d(Attachment a) {
  if (a == Attachment::plow) return {"x", "z", "theta_y", "psi", "w", "theta_v"};
  return {"x", "z", "theta_y", "w", "theta_v"};
}

// What each coordinate measures (Chapter II): X, Z and W translations; the
// pitch angles theta_y, theta_v and the linkage angle psi rotations.
std::vector<core::Quantity> coordinate_quantities_2d(Attachment a) {
  using core::Quantity;
  if (a == Attachment::plow) return {Quantity::length, Quantity::length, Quantity::angle, Quantity::angle, Quantity::length, Quantity::angle};
  return {Quantity::length, Quantity::length, Quantity::angle, Quantity::length, Quantity::angle};
}

std::vector<std::string> coordinate_names_3d(Attachment a) {
  std::vector<std::string> names{"x", "y", "z", "theta_x", "theta_y", "theta_z", "u", "v", "w", "theta_u", "theta_v", "theta_w", "eta"};
  if (a == Attachment::plow) {
    names.push_back("psi");
    names.push_back("alpha");
  }
  return names;
}

// What each coordinate measures (Chapter III): the frame's and the cab's
// X, Y, Z (x, y, z; u, v, w) translations, every theta, the axle's roll eta,
// the linkage's psi and alpha rotations.
std::vector<core::Quantity> coordinate_quantities_3d(Attachment a) {
  using core::Quantity;
  constexpr Quantity L = Quantity::length, A = Quantity::angle;
  std::vector<Quantity> q{L, L, L, A, A, A, L, L, L, A, A, A, A};
  if (a == Attachment::plow) {
    q.push_back(A);
    q.push_back(A);
  }
  return q;
}

// Rotation by `angle` about the unit axis `axis` (Rodrigues).
Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Eigen::Vector3d boom_plane_point(const Eigen::Vector2d& p, double offset) { return {p.x(), offset, p.y()}; }

// C with every element at full value, while cutting and while backing off
// (REC C5). The two models sum the soil's share in their own order (kept so
// that a damping update reproduces a fresh build bit for bit).
void assemble_damping(VehicleModel& vm) {
  const Multibody& mb = vm.multibody;
  vm.c_full = mb.damping_matrix();
  vm.c_cut = vm.c_full;
  const double reduction = 1.0 - vm.soil.damping_reduction;
  if (vm.dimensions == 2) {
    Eigen::MatrixXd c_soil = Eigen::MatrixXd::Zero(mb.size(), mb.size());
    for (int e : vm.soil_elements) {
      const Eigen::RowVectorXd g = mb.elongation_map(e);
      c_soil += vm.soil.damping * g.transpose() * g;
    }
    vm.c_back = vm.c_full - reduction * c_soil;
  } else {
    vm.c_back = vm.c_full;
    for (int e : vm.soil_elements) {
      const Eigen::RowVectorXd g = mb.elongation_map(e);
      vm.c_back -= reduction * mb.elements()[static_cast<std::size_t>(e)].damping * g.transpose() * g;
    }
  }
}

// The contact-consistent statics (Eqs. 11.1-11.4) and the contacts at rest.
void finish_contacts(VehicleModel& vm) {
  const Multibody& mb = vm.multibody;
  vm.input_elements.clear();
  for (std::size_t e = 0; e < vm.ground_inputs.size(); ++e)
    if (vm.ground_inputs[e].kind != GroundInput::Kind::none) vm.input_elements.push_back(static_cast<int>(e));
  vm.statics = solve_contact_statics(mb, gravity_force(mb, vm.gravity), vm.contact_definitions, vm.soil_elements, vm.contact_law);
  vm.contacts = UnilateralContacts{};
  vm.contacts.configure(mb, vm.contact_definitions, vm.statics.element_forces, vm.ground_inputs, vm.contact_law);
}

}  // namespace

int VehicleModel::coordinate(const std::string& name) const { return index_of(multibody.coordinate_names(), name); }

VehicleModel build_vehicle_model(const Machine2DParameters& p) {
  VehicleModel vm;
  vm.dimensions = 2;
  vm.attachment = p.attachment;
  vm.gravity = p.gravity;
  vm.multibody = Multibody(coordinate_names_2d(p.attachment), coordinate_quantities_2d(p.attachment));
  Multibody& mb = vm.multibody;
  const FrameMassProperties fmp = frame_mass_properties(p.frame, p.cab);
  vm.frame_cg = in_3d(fmp.cg);
  vm.reference = in_3d(fmp.reference);
  const std::vector<std::string>& names = mb.coordinate_names();
  const int n = mb.size();
  const int ix = index_of(names, "x"), iz = index_of(names, "z"), ity = index_of(names, "theta_y");
  const int iw = index_of(names, "w"), itv = index_of(names, "theta_v"), ipsi = index_of(names, "psi");
  const Eigen::Vector3d ref = in_3d(fmp.reference);

  // Frame: a point p moves by (x, z) + theta_y y x (p - ref).
  auto frame_jacobian = [&](const Eigen::Vector3d& point) {
    Jacobian j = Jacobian::Zero(3, n);
    j(X, ix) = 1.0;
    j(Z, iz) = 1.0;
    const Eigen::Vector3d turn = Eigen::Vector3d::UnitY().cross(point - ref);
    j.col(ity) += turn;
    return j;
  };
  Body frame;
  frame.name = "frame";
  frame.mass = fmp.mass;
  frame.inertia(Y, Y) = fmp.inertia;
  frame.translation = frame_jacobian(in_3d(fmp.cg));
  frame.rotation = Jacobian::Zero(3, n);
  frame.rotation(Y, ity) = 1.0;
  const int frame_body = mb.add_body(frame);

  // Cab: X tied to the frame at the cab's c.g., Z = w, pitch theta_v.
  Body cab;
  cab.name = "cab";
  cab.mass = p.cab.mass;
  cab.inertia(Y, Y) = p.cab.inertia;
  cab.translation = Jacobian::Zero(3, n);
  cab.translation.row(X) = frame_jacobian(in_3d(p.cab.cg)).row(X);
  cab.translation(Z, iw) = 1.0;
  cab.rotation = Jacobian::Zero(3, n);
  cab.rotation(Y, itv) = 1.0;
  const int cab_body = mb.add_body(cab);

  auto frame_point = [&](const std::string& name, const Eigen::Vector2d& p2) { return mb.add_point({name, frame_jacobian(in_3d(p2))}); };
  auto cab_point = [&](const std::string& name, const Eigen::Vector2d& p2) {
    return mb.add_body_point(name, cab_body, in_3d(p2 - p.cab.cg));
  };
  vm.frame_body = frame_body;
  vm.cab_body = cab_body;

  const Eigen::Vector3d ground_normal(std::sin(p.ground_slope), 0.0, std::cos(p.ground_slope));
  const Eigen::Vector3d ground_tangent(std::cos(p.ground_slope), 0.0, -std::sin(p.ground_slope));  // rearward along the ground
  vm.soil = p.soil;
  vm.soil_line_speed = p.forward_speed * std::cos(p.ground_slope);
  vm.soil_flow = Eigen::Vector3d(p.forward_speed * std::cos(p.ground_slope), 0.0, -p.forward_speed * std::sin(p.ground_slope));
  if (p.attachment == Attachment::chain) {
    vm.chain = p.chain;
    vm.chain_direction = Eigen::Vector3d(std::cos(p.chain.chain_angle), 0.0, -std::sin(p.chain.chain_angle));
    vm.chain_moment_arm = p.chain.moment_arm;
  }

  // Cab mounts (elements 12 and 14): vertical between frame and cab.
  for (const auto& [name, mount] : {std::pair<std::string, const CabMount*>{"cab_mount_front", &p.cab.front}, {"cab_mount_rear", &p.cab.rear}}) {
    const int a = frame_point(name + "_frame", mount->position);
    const int b = cab_point(name + "_cab", mount->position);
    mb.add_element({name, a, b, Eigen::Vector3d::UnitZ(), mount->vertical.stiffness, mount->vertical.damping});
  }
  // Tires: normal and tractive, at the contact points, to the ground.
  for (const auto& [name, tire] : {std::pair<std::string, const Tire2D*>{"front_tire", &p.front_tire}, {"rear_tire", &p.rear_tire}}) {
    const int c = frame_point(name + "_contact", tire->contact);
    mb.add_element({name + "_normal", c, -1, ground_normal, tire->normal.stiffness, tire->normal.damping});
    mb.add_element({name + "_tractive", c, -1, ground_tangent, tire->tractive.stiffness, tire->tractive.damping});
  }

  if (p.attachment == Attachment::plow) {
    const Plow2D& pl = p.plow;
    const Eigen::Vector2d ratios = four_bar_velocity_ratios(pl.linkage);  // (CB, lower arm)
    const double cb = ratios(0);
    // Upper arm: rotation psi about pin 6 (absolute). Pin 9 moves with it.
    const Jacobian j6 = frame_jacobian(in_3d(pl.linkage.upper_pivot));
    auto arm_point = [&](const Eigen::Vector2d& p2) {
      Jacobian j = j6;
      j.col(ipsi) += Eigen::Vector3d::UnitY().cross(in_3d(p2 - pl.linkage.upper_pivot));
      return j;
    };
    const Jacobian j9 = arm_point(pl.linkage.upper_joint);
    // Shank rotation phi_s = CB psi + (1 - CB) theta_y (Eq. A.10 in the +Y sense).
    Eigen::RowVectorXd shank_rotation = Eigen::RowVectorXd::Zero(n);
    shank_rotation(ipsi) = cb;
    shank_rotation(ity) = 1.0 - cb;
    auto shank_point = [&](const Eigen::Vector2d& p2) {
      Jacobian j = j9;
      j += Eigen::Vector3d::UnitY().cross(in_3d(p2 - pl.linkage.upper_joint)) * shank_rotation;
      return j;
    };
    Body plow;
    plow.name = "plow";
    plow.mass = pl.mass;
    plow.inertia(Y, Y) = pl.inertia;
    plow.translation = shank_point(pl.cg);
    plow.rotation = Jacobian::Zero(3, n);
    plow.rotation.row(Y) = shank_rotation;
    vm.plow_body = mb.add_body(plow);
    vm.blade_point = mb.add_point({"blade", shank_point(pl.blade_point)});
    vm.shaker_point = mb.add_point({"shaker", shank_point(pl.shaker_point)});
    const int bounce = mb.add_point({"bounce_tire", shank_point(pl.bounce_tire_point)});
    mb.add_element({"bounce_tire", bounce, -1, ground_normal, pl.bounce_tire.stiffness, pl.bounce_tire.damping});
    vm.shaker = {pl.shaker_amplitude, pl.shaker_frequency, pl.shaker_phase, in_3d((pl.linkage.upper_joint - pl.linkage.lower_joint).normalized())};
    const int cyl_frame = frame_point("lift_cylinder_frame", pl.cylinder_frame_point);
    const int cyl_arm = mb.add_point({"lift_cylinder_arm", arm_point(pl.cylinder_arm_point)});
    const Eigen::Vector2d axis = pl.cylinder_arm_point - pl.cylinder_frame_point;
    if (!(axis.norm() > 0.0)) throw std::invalid_argument("the lift cylinder has zero length");
    mb.add_element({"lift_cylinder", cyl_frame, cyl_arm, in_3d(axis), pl.lift_cylinder.stiffness, pl.lift_cylinder.damping});
  } else if (p.attachment == Attachment::chain) {
    vm.blade_point = frame_point("boom", p.chain.boom_point);
    vm.chain_point = frame_point("chain_pin", p.chain.chain_pin);
  }
  if (vm.blade_point >= 0) {
    vm.soil_elements.push_back(mb.add_element({"soil_x", vm.blade_point, -1, Eigen::Vector3d::UnitX(), p.soil.stiffness, p.soil.damping}));
    vm.soil_elements.push_back(mb.add_element({"soil_z", vm.blade_point, -1, Eigen::Vector3d::UnitZ(), p.soil.stiffness, p.soil.damping}));
  }

  check_definiteness(mb);
  vm.m = mb.mass_matrix();
  vm.k_full = mb.stiffness_matrix();
  vm.c_full = mb.damping_matrix();
  // The soil's share, to switch between full and reduced values.
  Eigen::MatrixXd k_soil = Eigen::MatrixXd::Zero(n, n);
  for (int e : vm.soil_elements) {
    const Eigen::RowVectorXd g = mb.elongation_map(e);
    k_soil += p.soil.stiffness * g.transpose() * g;
  }
  vm.k_cut = p.soil.cut_face ? Eigen::MatrixXd(vm.k_full - k_soil) : vm.k_full;  // cut-face reading: no spring while cutting
  vm.k_back = vm.k_full - (1.0 - p.soil.stiffness_reduction) * k_soil;
  assemble_damping(vm);
  vm.k_no_soil = vm.k_full - k_soil;
  vm.m_solver.compute(vm.m);

  // One-sided contacts: each tire's normal element with its tractive one, and the bounce tire.
  std::vector<ContactDefinition> contacts = {
      {"front_tire", mb.element_index("front_tire_normal"), {mb.element_index("front_tire_tractive")}},
      {"rear_tire", mb.element_index("rear_tire_normal"), {mb.element_index("rear_tire_tractive")}}};
  if (p.attachment == Attachment::plow) contacts.push_back({"bounce_tire", mb.element_index("bounce_tire"), {}});
  vm.contact_definitions = contacts;
  vm.contact_law = p.contacts;
  // Reference ground inputs (Eqs. 2.20, 2.26) of the tires and the bounce tire.
  vm.ground_inputs.assign(mb.elements().size(), GroundInput{});
  const std::pair<const char*, const GroundInput*> inputs[] = {{"front_tire_normal", &p.front_tire.normal_input},
                                                               {"front_tire_tractive", &p.front_tire.tractive_input},
                                                               {"rear_tire_normal", &p.rear_tire.normal_input},
                                                               {"rear_tire_tractive", &p.rear_tire.tractive_input},
                                                               {"bounce_tire", &p.plow.bounce_input}};
  for (const auto& [name, input] : inputs) {
    const int e = mb.element_index(name);
    if (e >= 0) vm.ground_inputs[static_cast<std::size_t>(e)] = *input;
  }
  finish_contacts(vm);
  return vm;
}

VehicleModel build_vehicle_model(const Machine3DParameters& p) {
  VehicleModel vm;
  vm.dimensions = 3;
  vm.attachment = p.attachment;
  vm.gravity = p.gravity;
  vm.multibody = Multibody(coordinate_names_3d(p.attachment), coordinate_quantities_3d(p.attachment));
  Multibody& mb = vm.multibody;
  int reel_body = -1, rear_axle_body = -1, front_axle_body = -1, cab_body = -1, plow_body = -1;
  const std::vector<std::string>& names = mb.coordinate_names();
  const int n = mb.size();
  auto col = [&](const char* c) { return index_of(names, c); };
  const int ix = col("x"), iy = col("y"), iz = col("z"), itx = col("theta_x"), ity = col("theta_y"), itz = col("theta_z");
  const int iu = col("u"), iv = col("v"), iw = col("w"), itu = col("theta_u"), itv = col("theta_v"), itw = col("theta_w");
  const int ieta = col("eta"), ipsi = col("psi"), ialpha = col("alpha");

  // Reference point of x, y, z: the frame assembly's c.g. with the front axle (Eqs. F.1, F.2, F.4) unless given.
  {
    std::vector<RigidPart3D> all = p.frame.parts;
    all.push_back(p.frame.reel_and_carrier);
    all.push_back(p.frame.rear_axle);
    all.push_back(p.front_axle.axle);
    vm.reference = p.frame.reference ? *p.frame.reference : combine(all, "frame assembly").cg;
  }

  // Frame: a point p moves by (x, y, z) + theta x (p - ref)  (Eq. 3.3).
  Jacobian frame_rotation = Jacobian::Zero(3, n);
  frame_rotation(X, itx) = frame_rotation(Y, ity) = frame_rotation(Z, itz) = 1.0;
  auto frame_jacobian = [&](const Eigen::Vector3d& point) {
    Jacobian j = Jacobian::Zero(3, n);
    j(X, ix) = j(Y, iy) = j(Z, iz) = 1.0;
    j -= skew(point - vm.reference) * frame_rotation;
    return j;
  };
  auto rigid_body = [&](const RigidPart3D& part, const Jacobian& translation, const Jacobian& rotation_jacobian) {
    Body b;
    b.name = part.name;
    b.mass = part.mass;
    b.inertia = part.inertia;
    b.translation = translation;
    b.rotation = rotation_jacobian;
    return mb.add_body(b);
  };
  const RigidPart3D frame_part = combine(p.frame.parts, "frame");
  vm.frame_body = rigid_body(frame_part, frame_jacobian(frame_part.cg), frame_rotation);
  reel_body = rigid_body(p.frame.reel_and_carrier, frame_jacobian(p.frame.reel_and_carrier.cg), frame_rotation);
  rear_axle_body = rigid_body(p.frame.rear_axle, frame_jacobian(p.frame.rear_axle.cg), frame_rotation);
  auto frame_point = [&](const std::string& name, const Eigen::Vector3d& point) { return mb.add_point({name, frame_jacobian(point)}); };

  // Front axle: pinned at point 20, angular velocity (eta', theta_y', theta_z') (Table II, Eq. 3.4).
  {
    Jacobian rot = Jacobian::Zero(3, n);
    rot(X, ieta) = 1.0;
    rot(Y, ity) = 1.0;
    rot(Z, itz) = 1.0;
    const Jacobian pin = frame_jacobian(p.front_axle.pin);
    front_axle_body = rigid_body(p.front_axle.axle, pin - skew(p.front_axle.axle.cg - p.front_axle.pin) * rot, rot);
  }

  // Cab: six coordinates of its own (Eq. 3.7).
  {
    Jacobian t = Jacobian::Zero(3, n), r = Jacobian::Zero(3, n);
    t(X, iu) = t(Y, iv) = t(Z, iw) = 1.0;
    r(X, itu) = r(Y, itv) = r(Z, itw) = 1.0;
    cab_body = rigid_body(p.cab.body, t, r);
  }
  for (const CabMount3D& mount : p.cab.mounts) {
    const int a = frame_point("cab_mount_" + mount.name + "_frame", mount.position);
    const int b = mb.add_body_point("cab_mount_" + mount.name + "_cab", cab_body, mount.position - p.cab.body.cg);
    const std::pair<const char*, const SpringDamperValues*> axes[] = {{"x", &mount.x}, {"y", &mount.y}, {"z", &mount.z}};
    for (int k = 0; k < 3; ++k)
      mb.add_element({"cab_mount_" + mount.name + "_" + axes[k].first, a, b, Eigen::Vector3d::Unit(k), axes[k].second->stiffness,
                          axes[k].second->damping});
  }

  // Tires: ground axes (slope about Y), wheel axes turned by the steering angle about the normal.
  const double g = p.ground_slope;
  const Eigen::Vector3d normal(std::sin(g), 0.0, std::cos(g)), tangent(std::cos(g), 0.0, -std::sin(g)), side = Eigen::Vector3d::UnitY();
  auto add_tire = [&](const std::string& name, const Tire3D& tire, double delta, bool on_front_axle) {
    const int c = on_front_axle ? mb.add_body_point(name + "_contact", front_axle_body, tire.contact - p.front_axle.axle.cg)
                                : frame_point(name + "_contact", tire.contact);
    // Rolling direction (rearward sense) and axle direction of a wheel steered by delta to the right:
    // its forward heading -longitudinal = (-cos delta, sin delta) in the ground plane.
    const Eigen::Vector3d longitudinal = std::cos(delta) * tangent - std::sin(delta) * side;
    const Eigen::Vector3d lateral = std::sin(delta) * tangent + std::cos(delta) * side;
    mb.add_element({name + "_vertical", c, -1, normal, tire.vertical.stiffness, tire.vertical.damping});
    mb.add_element({name + "_longitudinal", c, -1, longitudinal, tire.longitudinal.stiffness, tire.longitudinal.damping});
    mb.add_element({name + "_lateral", c, -1, lateral, tire.lateral.stiffness, tire.lateral.damping});
  };
  add_tire("front_left_tire", p.front_tires.left, p.front_tires.steering_angle, true);
  add_tire("front_right_tire", p.front_tires.right, p.front_tires.steering_angle, true);
  add_tire("rear_left_tire", p.rear_tires.left, p.rear_tires.steering_angle, false);
  add_tire("rear_right_tire", p.rear_tires.right, p.rear_tires.steering_angle, false);

  // Soil directions: along the travel (rearward relative to the ground), across it, vertical.
  vm.cut_direction = Eigen::Vector3d(std::cos(p.travel_angle), -std::sin(p.travel_angle), 0.0);
  vm.soil = p.soil;
  // The ground streams rearward past the machine at VS along the heading of travel in the
  // ground plane (the tires' ground, slope about Y; a wheel's rolling direction at delta = the
  // heading): the soil dampers' reference velocity and the velocity the soil springs' anchor
  // moves at under soil_line and cut_face (docs/theory/rigid.md section 18). The soil line
  // moves along the cut at its component on c; with heading 0 both are the 2-D model's
  // (VS cos theta_g, 0, -VS sin theta_g) and VS cos theta_g.
  const Eigen::Vector3d travel = std::cos(p.travel_angle) * tangent - std::sin(p.travel_angle) * side;
  vm.soil_flow = p.forward_speed * travel;
  // c . soil_flow = VS (cos^2 tau cos theta_g + sin^2 tau), written so that it is VS cos theta_g
  // exactly at tau = 0 and VS exactly on level ground.
  const double sin_tau = std::sin(p.travel_angle);
  vm.soil_line_speed = p.forward_speed * (std::cos(g) + sin_tau * sin_tau * (1.0 - std::cos(g)));
  if (p.attachment == Attachment::chain) {
    vm.chain = p.chain;
    vm.chain_direction = Eigen::Vector3d(std::cos(p.chain.chain_angle), 0.0, -std::sin(p.chain.chain_angle));
    vm.chain_moment_arm = p.chain.moment_arm;
  }

  if (p.attachment == Attachment::plow) {
    const Plow3D& pl = p.plow;
    const Eigen::Vector2d ratios = four_bar_velocity_ratios(pl.linkage);
    vm.linkage_ratio = ratios(0);
    // Placement (Appendix E): blade-plane points turned by beta about the shank axis (Eq. E.8), then every
    // plow point by alpha' about the vertical through the swing pin.
    const Eigen::Vector3d p9 = boom_plane_point(pl.linkage.upper_joint, pl.boom_offset);
    const Eigen::Vector3d p10 = boom_plane_point(pl.linkage.lower_joint, pl.boom_offset);
    const Eigen::Matrix3d blade_turn = rotation(p9 - p10, -pl.blade_angle);
    const Eigen::Matrix3d swing = rotation(Eigen::Vector3d::UnitZ(), pl.boom_angle);
    auto place = [&](const Eigen::Vector3d& r) { return Eigen::Vector3d(pl.swing_pin + swing * (r - pl.swing_pin)); };
    auto place_blade = [&](const Eigen::Vector2d& r) { return place(p9 + blade_turn * (boom_plane_point(r, pl.boom_offset) - p9)); };
    PlowPlacement& pp = vm.plow_placement;
    pp.pin6 = place(boom_plane_point(pl.linkage.upper_pivot, pl.boom_offset));
    pp.pin11 = place(boom_plane_point(pl.linkage.lower_pivot, pl.boom_offset));
    pp.pin9 = place(p9);
    pp.pin10 = place(p10);
    pp.cg = place_blade(pl.cg);
    pp.blade = place_blade(pl.blade_point);
    pp.shaker = place_blade(pl.shaker_point);
    pp.bounce = place_blade(pl.bounce_tire_point);
    pp.cylinder_base = place(boom_plane_point(pl.cylinder_base, pl.boom_offset));
    pp.cylinder_arm = place(boom_plane_point(pl.cylinder_arm_point, pl.boom_offset));
    pp.pin_axis = swing * Eigen::Vector3d::UnitY();
    pp.inertia = swing * pl.inertia_boom_axes * swing.transpose();
    const Eigen::Vector3d& ep = pp.pin_axis;
    vm.shaker = {pl.shaker_amplitude, pl.shaker_frequency, pl.shaker_phase, (pp.pin9 - pp.pin10).normalized()};  // Eq. 3.12, along l2

    // Swing carrier (massless): pinned at 19 about the frame's vertical, yaw alpha absolute (Table II: wZ = alpha').
    Jacobian carrier_rotation = frame_rotation;
    carrier_rotation.row(Z).setZero();
    carrier_rotation(Z, ialpha) = 1.0;
    const Jacobian j19 = frame_jacobian(pl.swing_pin);
    auto carrier_point = [&](const Eigen::Vector3d& r) { return Jacobian(j19 - skew(r - pl.swing_pin) * carrier_rotation); };
    // Upper arm: its rotation about the pin axis is psi (absolute); other components are the carrier's.
    Eigen::RowVectorXd e_psi = Eigen::RowVectorXd::Zero(n);
    e_psi(ipsi) = 1.0;
    const Eigen::RowVectorXd carrier_about_pin = ep.transpose() * carrier_rotation;
    const Jacobian arm_rotation = carrier_rotation + ep * (e_psi - carrier_about_pin);
    const Jacobian j6 = carrier_point(pp.pin6);
    auto arm_point = [&](const Eigen::Vector3d& r) { return Jacobian(j6 - skew(r - pp.pin6) * arm_rotation); };
    // Shank (link l2, the plow): about the pin axis CB psi + (1 - CB) theta (Eqs. E.6, E.7 in the +e_p sense).
    const Jacobian shank_rotation = carrier_rotation + ep * (vm.linkage_ratio * (e_psi - carrier_about_pin));
    const Jacobian j9 = arm_point(pp.pin9);
    auto shank_point = [&](const Eigen::Vector3d& r) { return Jacobian(j9 - skew(r - pp.pin9) * shank_rotation); };

    RigidPart3D plow_part{"plow", pl.mass, pp.cg, pp.inertia};
    plow_body = rigid_body(plow_part, shank_point(pp.cg), shank_rotation);
    vm.blade_point = mb.add_point({"blade", shank_point(pp.blade)});
    vm.shaker_point = mb.add_point({"shaker", shank_point(pp.shaker)});
    const int bounce = mb.add_point({"bounce_tire", shank_point(pp.bounce)});
    mb.add_element({"bounce_tire", bounce, -1, normal, pl.bounce_tire.stiffness, pl.bounce_tire.damping});
    const Eigen::Vector3d axis = pp.cylinder_arm - pp.cylinder_base;
    if (!(axis.norm() > 0.0)) throw std::invalid_argument("the lift cylinder has zero length");
    const int cb = mb.add_point({"lift_cylinder_base", carrier_point(pp.cylinder_base)});
    const int ca = mb.add_point({"lift_cylinder_arm", arm_point(pp.cylinder_arm)});
    mb.add_element({"lift_cylinder", cb, ca, axis, pl.lift_cylinder.stiffness, pl.lift_cylinder.damping});
    // K30 as a tangential spring at unit arm from the swing pin: elongation = 1 m * (alpha - theta_z), so k = K30 / (1 m)^2.
    const Eigen::Vector3d boom_direction = swing * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d arm_end = pl.swing_pin + boom_direction;
    const int sf = frame_point("swing_spring_frame", arm_end);
    const int sc = mb.add_point({"swing_spring_boom", carrier_point(arm_end)});
    mb.add_element({"swing_spring", sf, sc, Eigen::Vector3d::UnitZ().cross(boom_direction), pl.swing_spring.stiffness, pl.swing_spring.damping});
  } else if (p.attachment == Attachment::chain) {
    vm.blade_point = frame_point("boom", p.chain.boom_point);
    vm.chain_point = frame_point("chain_pin", p.chain.chain_pin);
  }
  if (vm.blade_point >= 0) {
    const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(vm.cut_direction);
    vm.soil_elements.push_back(mb.add_element({"soil_along", vm.blade_point, -1, vm.cut_direction, p.soil.stiffness, p.soil.damping}));
    vm.soil_elements.push_back(mb.add_element({"soil_across", vm.blade_point, -1, across, p.soil_lateral.stiffness, p.soil_lateral.damping}));
    vm.soil_elements.push_back(mb.add_element({"soil_vertical", vm.blade_point, -1, Eigen::Vector3d::UnitZ(), p.soil.stiffness, p.soil.damping}));
  }
  vm.frame_cg = frame_part.cg;
  // Reference ground inputs of the tires and the bounce tire (Eq. 1.5).
  vm.ground_inputs.assign(mb.elements().size(), GroundInput{});
  const std::pair<const char*, const Tire3D*> tires[] = {{"front_left_tire", &p.front_tires.left},
                                                          {"front_right_tire", &p.front_tires.right},
                                                          {"rear_left_tire", &p.rear_tires.left},
                                                          {"rear_right_tire", &p.rear_tires.right}};
  for (const auto& [prefix, tire] : tires) {
    vm.ground_inputs[static_cast<std::size_t>(mb.element_index(std::string(prefix) + "_vertical"))] = tire->vertical_input;
    vm.ground_inputs[static_cast<std::size_t>(mb.element_index(std::string(prefix) + "_longitudinal"))] = tire->longitudinal_input;
  }
  if (p.attachment == Attachment::plow) vm.ground_inputs[static_cast<std::size_t>(mb.element_index("bounce_tire"))] = p.plow.bounce_input;

  check_definiteness(mb);
  vm.m = mb.mass_matrix();
  vm.k_full = mb.stiffness_matrix();
  vm.k_cut = vm.k_full;
  vm.k_back = vm.k_full;
  vm.k_no_soil = vm.k_full;
  for (int e : vm.soil_elements) {
    const Eigen::RowVectorXd gmap = mb.elongation_map(e);
    const SpringDamper& el = mb.elements()[static_cast<std::size_t>(e)];
    if (p.soil.cut_face) vm.k_cut -= el.stiffness * gmap.transpose() * gmap;
    vm.k_no_soil -= el.stiffness * gmap.transpose() * gmap;
    vm.k_back -= (1.0 - p.soil.stiffness_reduction) * el.stiffness * gmap.transpose() * gmap;
  }
  assemble_damping(vm);
  vm.m_solver.compute(vm.m);

  // One-sided contacts: each tire's vertical element with its longitudinal and lateral ones, and the bounce tire.
  std::vector<ContactDefinition> contacts;
  for (const char* tire : {"front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire"}) {
    const std::string n(tire);
    contacts.push_back({n, mb.element_index(n + "_vertical"), {mb.element_index(n + "_longitudinal"), mb.element_index(n + "_lateral")}});
  }
  if (p.attachment == Attachment::plow) contacts.push_back({"bounce_tire", mb.element_index("bounce_tire"), {}});
  vm.contact_definitions = contacts;
  vm.contact_law = p.contacts;
  finish_contacts(vm);
  vm.reel_body = reel_body;
  vm.rear_axle_body = rear_axle_body;
  vm.front_axle_body = front_axle_body;
  vm.cab_body = cab_body;
  vm.plow_body = plow_body;
  return vm;
}


void set_shaker(VehicleModel& model, double amplitude, double frequency, double phase) {
  model.shaker.amplitude = amplitude;
  model.shaker.frequency = frequency;
  model.shaker.phase = phase;
}

void set_element_damping(VehicleModel& model, const std::string& name, double damping) {
  const int e = model.multibody.element_index(name);
  if (e < 0) throw std::invalid_argument("set_element_damping: the model has no element '" + name + "'");
  if (std::find(model.soil_elements.begin(), model.soil_elements.end(), e) != model.soil_elements.end())
    throw std::invalid_argument("set_element_damping: '" + name + "' is a soil element: change the soil law and rebuild the model");
  if (!(damping >= 0.0)) throw std::invalid_argument("set_element_damping: damping must be >= 0");
  model.multibody.element(e).damping = damping;
  assemble_damping(model);
  // The statics do not depend on damping, but which contacts exist does (a
  // contact with neither stiffness nor damping is left out): redone as a build does.
  finish_contacts(model);
}

Eigen::MatrixXd modal_stiffness(const VehicleModel& model, ModalSoil soil) {
  Eigen::MatrixXd k = soil == ModalSoil::cutting ? model.k_cut : soil == ModalSoil::backing ? model.k_back : model.k_no_soil;
  remove_lifted_contacts(model.multibody, model.statics, k);  // Eq. 11.7
  return k;
}

Jacobian frame_point_jacobian(const VehicleModel& model, const Eigen::Vector3d& point) {
  // The frame body's own Jacobian moved to another point of the frame.
  const Body& frame = model.multibody.bodies()[static_cast<std::size_t>(model.frame_body)];
  return frame.translation - skew(point - model.frame_cg) * frame.rotation;
}

const GroundInput* ground_input_of(const VehicleModel& model, int element) {
  const GroundInput& in = model.ground_inputs.at(static_cast<std::size_t>(element));
  return in.kind != GroundInput::Kind::none ? &in : nullptr;
}

}  // namespace framedyn::rigid
