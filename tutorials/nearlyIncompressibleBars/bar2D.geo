// One bar of benchmark B2 (doc/benchmarks.md): the rectangle [x0, x0+L] x
// [-W/2, W/2] of structured right-angled triangles (nx by ny squares, each
// cut in two), extruded one layer of thickness t along z (prisms) for
// plane strain.  Bar Two (contactEnd = 0) is meshed as the mirror image
// of Bar One, so that the two contact faces match point for point and stay
// matched while they slide (frictionless contact of mirrored bodies).
// Patches:
//   contact    the end facing the other bar (contactEnd = 1: at x0+L)
//   end        the other end
//   sides      y = -W/2 and y = W/2
//   frontBack  z = 0 and z = t (symmetry: plane strain)
DefineConstant[ x0 = 0, L = 32.4e-3, W = 6.4e-3, nx = 80, ny = 16,
                contactEnd = 1 ];
// t: the plane-strain layer's thickness, by default one cell across; two
// bodies in contact need the same t (-setnumber t), else the thinner one
// takes the thicker one's force over less depth
DefineConstant[ t = W/ny ];
e = 1e-6*L;
// Corners listed from the end to the contact face: mirrored for Bar Two
sx = (contactEnd == 1) ? 1 : -1;
xe = (contactEnd == 1) ? x0 : x0 + L;
Point(1) = {xe, -W/2, 0};
Point(2) = {xe + sx*L, -W/2, 0};
Point(3) = {xe + sx*L, W/2, 0};
Point(4) = {xe, W/2, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
ext[] = Extrude{0, 0, t} { Surface{1}; Layers{1}; Recombine; };
// ext: [top, volume, y = -W/2, contact face, y = W/2, end face]
Physical Surface("contact") = {ext[3]};
Physical Surface("end") = {ext[5]};
Physical Surface("sides") = {ext[2], ext[4]};
Physical Surface("frontBack") = {1, ext[0]};
Physical Volume("bar") = {ext[1]};
