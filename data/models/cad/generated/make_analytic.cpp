// SPDX-License-Identifier: MIT
// Writes the small STEP/IGES test files of this folder with OpenCASCADE:
// analytic surfaces (planes, sphere, torus, cylinder with trimmed caps, a
// revolved B-spline curve) and surfaces without an exact NURBS form of degree
// <= 9 (an offset B-spline surface, a degree-11 Bezier patch).
//   g++ -std=c++17 -I/usr/include/opencascade make_analytic.cpp -o make_analytic \
//     -lTKSTEP -lTKIGES -lTKXSBase -lTKPrim -lTKTopAlgo -lTKBRep -lTKG3d -lTKG2d \
//     -lTKGeomBase -lTKMath -lTKernel
//   ./make_analytic   (in this folder)
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include <cstdio>

static void step(const TopoDS_Shape& s, const char* file) {
    STEPControl_Writer w;
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    if (w.Transfer(s, STEPControl_AsIs) != IFSelect_RetDone || w.Write(file) != IFSelect_RetDone)
        std::printf("failed: %s\n", file);
}

int main() {
    // A 2 x 3 x 4 box: six planes bounded by parameter lines.
    step(BRepPrimAPI_MakeBox(gp_Pnt(1, 2, 3), 2, 3, 4).Shape(), "box.step");
    // Sphere of radius 2 about (1, 0, 0): one face, poles and a seam.
    step(BRepPrimAPI_MakeSphere(gp_Pnt(1, 0, 0), 2).Shape(), "sphere.step");
    // Torus R = 3, r = 1 about the z axis.
    step(BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 3, 1).Shape(), "torus.step");
    // Cylinder r = 1, h = 2: its side is whole, its two disc caps are trimmed planes.
    step(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1, 2).Shape(),
         "cylinder.step");
    // A cubic B-spline profile in the xz plane revolved half a turn about z.
    {
        TColgp_Array1OfPnt poles(1, 4);
        poles(1) = gp_Pnt(1, 0, 0);
        poles(2) = gp_Pnt(2, 0, 1);
        poles(3) = gp_Pnt(1.5, 0, 2);
        poles(4) = gp_Pnt(1, 0, 3);
        TColStd_Array1OfReal knots(1, 2);
        knots(1) = 0, knots(2) = 1;
        TColStd_Array1OfInteger mults(1, 2);
        mults.Init(4);
        Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, knots, mults, 3);
        step(BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeEdge(c).Edge(),
                                   gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI)
                 .Shape(),
             "revolved.step");
    }
    // The plane z = 0 over [0, 2] x [0, 1] as a bicubic B-spline, offset by 0.5:
    // OpenCASCADE knows no exact form for it.
    {
        TColgp_Array2OfPnt poles(1, 4, 1, 4);
        for (int i = 1; i <= 4; ++i)
            for (int j = 1; j <= 4; ++j)
                poles(i, j) = gp_Pnt(2.0 * (i - 1) / 3, (j - 1) / 3.0, 0.0);
        TColStd_Array1OfReal knots(1, 2);
        knots(1) = 0, knots(2) = 1;
        TColStd_Array1OfInteger mults(1, 2);
        mults.Init(4);
        Handle(Geom_BSplineSurface) s =
            new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
        Handle(Geom_OffsetSurface) o = new Geom_OffsetSurface(s, 0.5);
        step(BRepBuilderAPI_MakeFace(o, 1e-7).Face(), "offset.step");
    }
    // z = x * y over [0, 1]^2 written as a degree-11 Bezier patch (above our
    // degree 9), as IGES.
    {
        TColgp_Array2OfPnt poles(1, 12, 1, 12);
        for (int i = 1; i <= 12; ++i)
            for (int j = 1; j <= 12; ++j) {
                const double x = (i - 1) / 11.0, y = (j - 1) / 11.0;
                poles(i, j) = gp_Pnt(x, y, x * y);
            }
        Handle(Geom_BezierSurface) b = new Geom_BezierSurface(poles);
        IGESControl_Controller::Init();
        IGESControl_Writer w("MM", 0);
        w.AddShape(BRepBuilderAPI_MakeFace(b, 1e-7).Face());
        w.ComputeModel();
        if (!w.Write("degree11.igs")) std::printf("failed: degree11.igs\n");
    }
    return 0;
}
