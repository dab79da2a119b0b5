# fkSGP on soma's bench pool (bench/stewart.cpp: seed 20261130, 32 platforms), written to pool.txt by
# stewart_pool.cpp (same directory). Not part of soma's build or CI. In the scratch folder:
#   g++ -std=gnu++20 -O2 -I<soma>/algebra/include -isystem /usr/include/eigen3 stewart_pool.cpp \
#       <soma>/build/release/algebra/libsoma_algebra.a -lmpfr -lgmp -lquadmath -o pool && ./pool > pool.txt
#   OMP_NUM_THREADS=1 /usr/bin/python3 stewart_fksgp_pool.py
import sys, time, numpy as np
sys.path.insert(0, ".")
from python import solver66
rows = np.loadtxt("pool.txt")
reps = 3
times=[]; counts=[]; worst=[]; nreal=[]
for rep in range(reps):
  for r in rows:
    B = r[:18].reshape(6,3); P = r[18:36].reshape(6,3); legs = r[36:42]
    X = B - B[0]; x = P - P[0]; L = legs**2
    t0=time.process_time(); Rt,err = solver66(X,x,L,0); times.append(time.process_time()-t0)
    if rep: continue
    counts.append(Rt.shape[0]); size=np.max(np.abs(np.vstack([X,x]))); wr=0.0; nr=0
    for M in Rt:
      if np.max(np.abs(M.imag)) < 1e-8:
        R,t = M[:,:3].real, M[:,3].real; nr+=1
        wr=max(wr, np.max(np.abs(np.sqrt(np.sum((R@x.T + t[:,None] - X.T)**2,axis=0)) - legs))/size)
    worst.append(wr); nreal.append(nr)
t=np.array(times)*1e3; w=np.array(worst)
print(f"soma bench pool: {len(rows)} platforms x {reps}; median {np.median(t):.2f} ms CPU, p90 {np.percentile(t,90):.2f}")
print(f"40 returned {sum(c==40 for c in counts)}/{len(rows)}; mean real {np.mean(nreal):.2f}; real residual/size median {np.median(w):.2e} worst {w.max():.2e}")
