# fkSGP on soma's bench pool (bench/stewart.cpp: seed 20261130, 32 platforms), written to pool.txt by
# stewart_pool.cpp (same directory). Not part of soma's build or CI. In the scratch folder:
#   g++ -std=gnu++20 -O2 -I<soma>/algebra/include -isystem /usr/include/eigen3 stewart_pool.cpp \
#       <soma>/build/release/algebra/libsoma_algebra.a -lmpfr -lgmp -lquadmath -o pool && ./pool > pool.txt
#   OMP_NUM_THREADS=1 /usr/bin/python3 stewart_fksgp_pool.py            # fkSGP's times and counts
#   /usr/bin/python3 stewart_fksgp_pool.py --platforms                  # pool_k.json, soma's platform files
#   for k in $(seq 0 31); do <soma>/build/release/cli/soma stewart pool_$k.json --json > soma_$k.json; done
#   OMP_NUM_THREADS=1 /usr/bin/python3 stewart_fksgp_pool.py            # now also per platform against soma
import sys, os, json, time, numpy as np
sys.path.insert(0, ".")
rows = np.loadtxt("pool.txt")
if "--platforms" in sys.argv:
  for k, r in enumerate(rows):
    json.dump({"name": f"bench pool {k}", "base": r[:18].reshape(6, 3).tolist(),
               "platform": r[18:36].reshape(6, 3).tolist(), "leg_lengths": r[36:42].tolist()},
              open(f"pool_{k}.json", "w"))
  sys.exit(0)
from python import solver66
reps = 3
times=[]; counts=[]; worst=[]; nreal=[]; postures=[]
for rep in range(reps):
  for r in rows:
    B = r[:18].reshape(6,3); P = r[18:36].reshape(6,3); legs = r[36:42]
    X = B - B[0]; x = P - P[0]; L = legs**2
    t0=time.process_time(); Rt,err = solver66(X,x,L,0); times.append(time.process_time()-t0)
    if rep: continue
    counts.append(Rt.shape[0]); size=np.max(np.abs(np.vstack([X,x]))); wr=0.0; nr=0; ps=[]
    for M in Rt:
      if np.max(np.abs(M.imag)) < 1e-8:
        R,t = M[:,:3].real, M[:,3].real; nr+=1
        wr=max(wr, np.max(np.abs(np.sqrt(np.sum((R@x.T + t[:,None] - X.T)**2,axis=0)) - legs))/size)
        ps.append((R, t - R@P[0] + B[0]))  # back to the platform file's frames: p -> R p + t
    worst.append(wr); nreal.append(nr); postures.append(ps)
t=np.array(times)*1e3; w=np.array(worst)
print(f"soma bench pool: {len(rows)} platforms x {reps}; median {np.median(t):.2f} ms CPU, p90 {np.percentile(t,90):.2f}")
print(f"40 returned {sum(c==40 for c in counts)}/{len(rows)}; mean real {np.mean(nreal):.2f}; real residual/size median {np.median(w):.2e} worst {w.max():.2e}")
# Per platform against soma's real postures (soma_k.json, when present): the same real count, and
# each fkSGP posture at its nearest soma posture (max over the entries of R and t).
if all(os.path.exists(f"soma_{k}.json") for k in range(len(rows))):
  same=0; far=0.0; fast=0
  for k in range(len(rows)):
    s = json.load(open(f"soma_{k}.json")); fast += s.get("tracker") == "fast"
    soma = [(np.array(p["rotation"], dtype=float), np.array(p["translation"], dtype=float)) for p in s["solutions"]]
    same += len(soma) == nreal[k]
    for R, tt in postures[k]:
      far = max(far, min(max(np.max(np.abs(R - Rs)), np.max(np.abs(tt - ts))) for Rs, ts in soma))
  print(f"per platform against soma: same real count {same}/{len(rows)} (soma's fast tracker on {fast}); "
        f"fkSGP's real postures within {far:.2e} of soma's (max over R and t entries)")
