// One ring of benchmark B1 (doc/benchmarks.md): annulus of outer radius Ro and
// inner radius Ri centred at (cx, 0), four structured blocks (the quarter
// arcs between -45, 45, 135 and 225 degrees), nr cells across and nq along
// each quarter, triangles extruded one layer of thickness t along z for
// plane strain.  The points of the outer circle sit at the angles
// 2 pi k/(4 nq).  side = -1 meshes the mirror image (x -> -x about cx),
// so that two rings facing each other match point for point on their
// contact arcs and stay matched while they slide.  Patches:
//   contact    the outer quarter arc facing the other ring (side = 1: the
//              one around +x, side = -1: around -x)
//   outer      the rest of the outer circle
//   inner      the inner circle
//   frontBack  z = 0 and z = t (symmetry: plane strain)
DefineConstant[ cx = 0, Ro = 40e-3, Ri = 30e-3, nr = 10, nq = 31,
                side = 1 ];
// t: the plane-strain layer's thickness, by default one cell across; two
// bodies in contact need the same t (-setnumber t), else the thinner one
// takes the thicker one's force over less depth
DefineConstant[ t = (Ro - Ri)/nr ];
Point(1) = {cx, 0, 0};
For k In {0 : 3}
    a = Pi/4 + k*Pi/2;
    Point(10 + k) = {cx + side*Ri*Cos(a), Ri*Sin(a), 0};
    Point(20 + k) = {cx + side*Ro*Cos(a), Ro*Sin(a), 0};
    Line(10 + k) = {10 + k, 20 + k};
EndFor
For k In {0 : 3}
    k1 = (k + 1) % 4;
    Circle(20 + k) = {10 + k, 1, 10 + k1};     // inner arc
    Circle(30 + k) = {20 + k, 1, 20 + k1};     // outer arc
    Curve Loop(k + 1) = {10 + k, 30 + k, -(10 + k1), -(20 + k)};
    Plane Surface(k + 1) = {k + 1};
EndFor
Transfinite Curve{10:13} = nr + 1;
Transfinite Curve{20:23, 30:33} = nq + 1;
Transfinite Surface{1:4};

// Arcs k span from 45 + 90 k degrees (mirrored for side = -1): k = 3
// faces the other ring
kc = 3;
contact[] = {};
outer[] = {};
inner[] = {};
fb[] = {};
vol[] = {};
For k In {0 : 3}
    ext[] = Extrude{0, 0, t} { Surface{k + 1}; Layers{1}; Recombine; };
    // ext: [top, volume, laterals of lines 10+k, 30+k, 10+k1, 20+k]
    fb[] += {k + 1, ext[0]};
    vol[] += ext[1];
    If (k == kc)
        contact[] += ext[3];
    Else
        outer[] += ext[3];
    EndIf
    inner[] += ext[5];
EndFor
Physical Surface("contact") = contact[];
Physical Surface("outer") = outer[];
Physical Surface("inner") = inner[];
Physical Surface("frontBack") = fb[];
Physical Volume("ring") = vol[];
