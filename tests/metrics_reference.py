#!/usr/bin/env python3
# The expected values of tests/test_metrics.c, from an independent
# implementation in plain Python (double precision). It writes the fixture
# tests/fixtures/metrics_reference.txt, which test_metrics reads (ctest
# passes its path): "NAME VALUE" lines, "#" lines comments; ctest's
# fixture_metrics_reference checks that the file is this script's output.
# After a change here, regenerate it from the repository root and commit both:
#     python3 tests/metrics_reference.py > tests/fixtures/metrics_reference.txt
# Independent SSIM (Wang et al. 2004) with the test's window and border rule:
# 11-tap Gaussian sigma 1.5, edges replicated, luma of the encoded values.
import math
W,H=16,12
def pa(x,y): return 0.5+0.4*math.sin(0.7*x+0.3*y)*math.cos(0.5*y)
def pb(x,y): return min(1.0,max(0.0,pa(x,y)*0.9+0.05+0.03*math.sin(2.1*x*y)))
k=[math.exp(-i*i/(2*1.5*1.5)) for i in range(-5,6)]; s=sum(k); k=[v/s for v in k]
def lum(f): return [[f(x,y) for x in range(W)] for y in range(H)]  # grey: R=G=B
A=lum(pa); B=lum(pb)
def blur(img):
    cl=lambda v,n: 0 if v<0 else (n-1 if v>=n else v)
    t=[[sum(k[i+5]*img[y][cl(x+i,W)] for i in range(-5,6)) for x in range(W)] for y in range(H)]
    return [[sum(k[i+5]*t[cl(y+i,H)][x] for i in range(-5,6)) for x in range(W)] for y in range(H)]
prod=lambda P,Q: [[P[y][x]*Q[y][x] for x in range(W)] for y in range(H)]
ma,mb,maa,mbb,mab=blur(A),blur(B),blur(prod(A,A)),blur(prod(B,B)),blur(prod(A,B))
c1,c2=0.01**2,0.03**2
print("# Expected values for tests/test_metrics.c, written by tests/metrics_reference.py; do not")
print("# edit. Regenerate: python3 tests/metrics_reference.py > tests/fixtures/metrics_reference.txt")
print("# The textured pair (pattern_a against pattern_b, %dx%d, grey):" % (W, H))
tot=0
for y in range(H):
    for x in range(W):
        va=maa[y][x]-ma[y][x]**2; vb=mbb[y][x]-mb[y][x]**2; cv=mab[y][x]-ma[y][x]*mb[y][x]
        tot+=(2*ma[y][x]*mb[y][x]+c1)*(2*cv+c2)/((ma[y][x]**2+mb[y][x]**2+c1)*(va+vb+c2))
print("ssim %.17g"%(tot/(W*H)))
mse=sum((A[y][x]-B[y][x])**2 for y in range(H) for x in range(W))/(W*H)
print("psnr %.17g"%(-10*math.log10(mse)))
errs=sorted(abs(A[y][x]-B[y][x])*255 for y in range(H) for x in range(W))
r=math.ceil(0.99*len(errs)); print("p99 %.17g\nmax_error %.17g"%(errs[r-1],errs[-1]))
print("# Flat 0.5 against flat 0.6: SSIM's luminance term alone.")
print("flat_ssim %.17g"%((2*.5*.6+c1)/(.25+.36+c1)))
