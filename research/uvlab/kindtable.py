import os, sys; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import *
K=['artist','atlas','conformal']
vs=['a_draco','a_avg','b_portable','c_one','d_one','c_avg','d_avg','f_avg','h_med','h_wavg','h_qw','h_adapt2','h_blend']
for m in ('H0','Z2'):
  print('\nCost model %s (mpd order). Cells: median / mean of per-mesh ratio variant ÷ stock value bits.\n'%m)
  print('| variant | ' + ' | '.join('qt%d %s'%(qt,k) for qt in (10,12) for k in K) + ' | qt10 all-22 median (max) | qt12 all-22 median (max) |')
  print('|---|'+'---:|'*8)
  for v in vs:
    cells=[]
    for qt in (10,12):
      for k in K:
        rs=[cost(n,qt,'mpd',v,m)/stock_value_bits(n,qt) for n in REAL if kind(n)==k]
        cells.append('%.2f / %.2f'%(med(rs),mean(rs)))
    for qt in (10,12):
      rs=[cost(n,qt,'mpd',v,m)/stock_value_bits(n,qt) for n in REAL]
      cells.append('%.3f (%.2f)'%(med(rs),max(rs)))
    print('| %s | '%v+' | '.join(cells)+' |')
