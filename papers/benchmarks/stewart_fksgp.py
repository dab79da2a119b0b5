# fkSGP side-by-side driver (papers/benchmarks/stewart.md, issue 21 item 1). Not part of soma's
# build or CI. Run from a scratch folder that holds fkSGP's python/ package (martyushev/fkSGP,
# commit 8bd29e5781c8cb3eb16946d58a13cf554276dc9d; see stewart.md for the two local patches):
#   cd /work/scratch/fksgp && OMP_NUM_THREADS=1 /usr/bin/python3 stewart_fksgp.py 200
import sys, time, numpy as np
sys.path.insert(0, ".")
from python import genSGP, solver66
np.random.seed(20261130)
N = int(sys.argv[1]) if len(sys.argv) > 1 else 100
times=[]; counts=[]; worst_real=[]; gt_found=0; nreal=[]
for k in range(N):
    sgp = genSGP(1,1)
    X,x,L = sgp['X'],sgp['x'],sgp['L']
    t0=time.process_time(); Rt,err = solver66(X,x,L,0); times.append(time.process_time()-t0)
    counts.append(Rt.shape[0])
    size = np.max(np.abs(np.vstack([X,x])))
    best_gt = np.inf; wr=0.0; nr=0
    for i in range(Rt.shape[0]):
        M = Rt[i]
        if np.max(np.abs(M.imag)) < 1e-8:
            R,t = M[:,:3].real, M[:,3].real; nr+=1
            res = np.max(np.abs(np.sqrt(np.sum((R@x.T + t[:,None] - X.T)**2,axis=0)) - np.sqrt(L)))/size
            wr = max(wr,res)
            best_gt = min(best_gt, np.max(np.abs(R-sgp['Rgt'])) + np.max(np.abs(t-sgp['tgt'])))
    gt_found += best_gt < 1e-6; worst_real.append(wr); nreal.append(nr)
t=np.array(times)*1e3
print(f"platforms {N}; median {np.median(t):.2f} ms CPU, p90 {np.percentile(t,90):.2f}, mean {t.mean():.2f}")
print(f"40 returned: {sum(c==40 for c in counts)}/{N}; mean real {np.mean(nreal):.2f}; gt among real {gt_found}/{N}")
wr=np.array(worst_real); print(f"leg-length residual / size over real postures: median {np.median(wr):.2e}, worst {wr.max():.2e}")
