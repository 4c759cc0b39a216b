# Alternating runs of cmx and Galaxy Maps on the tiny cases, where start-up dominates; median and minimum wall ms of N runs each.
# Usage: python3 bench/map/tiny_peers.py CMX GALAXY_MAP PEERS_OUT N   (PEERS_OUT: the OUT of bench/map/peers.sh, which holds in_P0{1,3}_*.vtk)
import subprocess, time, statistics, sys
cmx, gm, d, n = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
import os
S = os.environ.get('SHARED_DATA', os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../shared/data'))
cases = {
 'gm_example': ([cmx,'map',f'{S}/galaxy-maps/example_object.vtk','--codomain',f'{S}/galaxy-maps/example_parameter.vtk'],
                [gm,f'{S}/galaxy-maps/example_object.vtk',f'{S}/galaxy-maps/example_parameter.vtk','-t','-o',f'{d}/tiny_gm_ex']),
 'P01': ([cmx,'map',None,'--boundary',f'{S}/public/P01/boundary.txt'],
         [gm,f'{d}/in_P01_object.vtk',f'{d}/in_P01_parameter.vtk','-t','-o',f'{d}/tiny_gm_P01']),
 'P03': ([cmx,'map',None,'--boundary',f'{S}/public/P03/boundary.txt'],
         [gm,f'{d}/in_P03_object.vtk',f'{d}/in_P03_parameter.vtk','-t','-o',f'{d}/tiny_gm_P03']),
}
import glob
for name,(c,g) in cases.items():
    if c[2] is None: c[2] = sorted(glob.glob(f'{S}/public/{name}/domain.*'))[0]
    c += ['-o', f'{d}/tiny_{name}', '--format', 'tmap,vtk', '--report', f'{d}/tiny_{name}.json', '--quiet']
    tc, tg = [], []
    for _ in range(n):
        for cmd, ts in ((c, tc), (g, tg)):
            t0 = time.perf_counter(); r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL); ts.append(time.perf_counter() - t0)
            assert r.returncode == 0, (cmd, r.returncode)
    print(f'| {name} | {n} | {statistics.median(tc)*1000:.1f} | {min(tc)*1000:.1f} | {statistics.median(tg)*1000:.1f} | {min(tg)*1000:.1f} | {statistics.median(tg)/statistics.median(tc):.2f} |')
