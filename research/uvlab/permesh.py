import os, sys; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import *
qt=int(sys.argv[1]); model=sys.argv[2]; vs=sys.argv[3].split(',')
print('mesh'.ljust(28),'kind'.ljust(9),'stockbpv', ' '.join(v[:12].rjust(12) for v in vs))
for n in MAN:
    sv=stock_value_bits(n,qt)
    print(n[:28].ljust(28),kind(n)[:9].ljust(9),('%.2f'%(sv/uvv(n))).rjust(8),' '.join(('%.3f'%(cost(n,qt,*v.split(':'),model)/sv)).rjust(12) for v in vs))
