"""Scan-line clouds (issues 5, 6, 7): points much denser along lines than across them.

Clouds (points of line l have ids l * N .. in line order; properties known by construction):
  sheet6, sheet12, sheet20  z = 0.1 sin(3x) on 16 lines y = 0.1 l, 150 / 300 / 500 points per
                            line 0.1 / A apart (A = 6, 12.5, 20): one open piece, one boundary
                            loop, every point used, the strip triangulation 2 (N - 1) per strip
  tilted                    the plane z = x on 16 lines y = l, 600 points 0.08 apart in x
                            (0.113 in space, 8.8x), the same expectations
  sphere40, sphere20        unit sphere on 40 (20) latitude circles of 500 (800) sin(theta) + 3
                            points (6.2x, 20x): closed, genus 0, 2V - 4 triangles
  cyl                       unit cylinder on 20 rings 0.2 apart of 300 points (9.5x)
Printed per cloud: CPU of Update (time.process_time), triangles, output points (more than n:
points added by the filter), used / unused points, boundary edges and loops, non-manifold edges
and vertices, components, genus, Euler characteristic, orientation, zero-area triangles, and
the triangles spanning more than two lines (skip), lying on one line (oneline) and touching an
added point (addedTris), from vtkReconstructionQuality.

Usage: /usr/bin/python3 Benchmarks/run_scanline_clouds.py <build>/lib/python3/dist-packages \
           <log|cdt|greedy> <cloud>...
"""
import sys, time, numpy as np
sys.path.insert(0, sys.argv[1])
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.util.numpy_support import vtk_to_numpy, numpy_to_vtk
import pointcloudsurface as pcs
FILTERS={'log':pcs.vtkLocalOptimumGrowth,'cdt':pcs.vtkCDTAdvancingFront,'greedy':pcs.vtkGreedySurfaceTriangulation}

def sheet(A, N, lines=16, d=0.1):
    P=[];L=[]
    for i in range(lines):
        x=np.arange(N)*d/A
        P.append(np.c_[x, np.full(N,i*d), 0.1*np.sin(3*x)]); L.append(np.full(N,i))
    return np.vstack(P), np.concatenate(L)
def tilted(lines=16, N=600):
    P=[];L=[]
    for i in range(lines):
        x=0.08*np.arange(N); P.append(np.c_[x,np.full(N,float(i)),x]); L.append(np.full(N,i))
    return np.vstack(P), np.concatenate(L)
def latsphere(circles, per):
    P=[];L=[]
    for i in range(circles):
        th=0.05+(np.pi-0.1)*i/(circles-1); n=int(per*np.sin(th))+3
        ph=2*np.pi*np.arange(n)/n
        P.append(np.c_[np.sin(th)*np.cos(ph),np.sin(th)*np.sin(ph),np.cos(th)*np.ones(n)]); L.append(np.full(n,i))
    return np.vstack(P), np.concatenate(L)
def cylinder(rings=20, per=300, h=0.2):
    P=[];L=[]
    for i in range(rings):
        ph=2*np.pi*np.arange(per)/per
        P.append(np.c_[np.cos(ph),np.sin(ph),np.full(per,i*h)]); L.append(np.full(per,i))
    return np.vstack(P), np.concatenate(L)
SHAPES={'sheet6':lambda:sheet(6,150),'sheet12':lambda:sheet(12.5,300),'sheet20':lambda:sheet(20,500),
 'tilted':tilted,'sphere40':lambda:latsphere(40,500),'sphere20':lambda:latsphere(20,800),'cyl':cylinder}
def poly(P):
    pd=vtkPolyData(); pts=vtkPoints(); pts.SetData(numpy_to_vtk(np.ascontiguousarray(P),deep=1)); pd.SetPoints(pts); return pd
filt=sys.argv[2]
for shape in sys.argv[3:]:
    P,L=SHAPES[shape]()
    f=FILTERS[filt](); f.SetInputData(poly(P)); t=time.process_time(); f.Update(); t=time.process_time()-t
    out=f.GetOutput(); 
    q=pcs.vtkReconstructionQuality(); q.SetInputData(out); q.Update(); fd=q.GetOutput().GetFieldData()
    g=lambda k: fd.GetArray(k).GetValue(0)
    F=vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1,3) if out.GetNumberOfPolys() else np.zeros((0,3),int)
    n=len(P); ok=(F<n).all(axis=1); Fl=L[F[ok]]
    span=Fl.max(1)-Fl.min(1)
    unused = f.GetNumberOfUnusedPoints() if hasattr(f,'GetNumberOfUnusedPoints') else -1
    print(f"{filt} {shape}: n={n} cpu={t:.2f} tris={int(g('NumberOfTriangles'))} outpts={out.GetNumberOfPoints()} used={int(g('NumberOfUsedPoints'))} unused={unused} bEdges={int(g('NumberOfBoundaryEdges'))} loops={int(g('NumberOfBoundaryLoops'))} nmE={int(g('NumberOfNonManifoldEdges'))} nmV={int(g('NumberOfNonManifoldVertices'))} comps={int(g('NumberOfConnectedComponents'))} genus={g('Genus')} euler={g('EulerCharacteristic')} orient={g('OrientationConsistency')} deg={int(g('NumberOfDegenerateTriangles'))} skip={(span>1).sum()} oneline={(span==0).sum()} addedTris={(~ok).sum()}", flush=True)
