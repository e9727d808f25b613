// A steel wing nut (lengths in mm), the object of scenes/wing_nut.toml.
// Regenerate the STL the scene reads with:
//   openscad -o scenes/meshes/wing_nut.stl scenes/meshes/wing_nut.scad
// Hub along z with a bolt hole; two wings in the x-z plane, 3 mm thick (y).
$fn = 40;

hub_r = 7;     // hub outer radius
hub_h = 9;     // hub height
hole_r = 3.2;  // M6 bolt clearance
wing_t = 3;    // wing thickness (y)

module wing(side) {
  // 2-D outline in (x, z), extruded along y and centred on the x-z plane.
  rotate([90, 0, 0]) linear_extrude(height = wing_t, center = true)
    hull() {
      translate([side * 5.5 - (side < 0 ? 1 : 0), 0.5]) square([1, 7.5]);
      translate([side * 19, 13]) circle(r = 5.5);
    }
}

difference() {
  union() {
    cylinder(h = hub_h, r = hub_r);
    wing(1);
    wing(-1);
  }
  translate([0, 0, -1]) cylinder(h = hub_h + 2, r = hole_r);
}
