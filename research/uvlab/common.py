import csv, collections, os, statistics, math
HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, 'out') + '/'
CORPUS = os.environ.get('CORPUS', os.path.join(HERE, '..', '..', '..', 'shared', 'corpus'))
MAN=collections.OrderedDict((r['name'],r) for r in csv.DictReader(open(os.path.join(CORPUS, 'MANIFEST.tsv')),delimiter='\t'))
INFO={}
for l in open(D+'meshinfo.tsv'):
    f=l.rstrip('\n').split('\t'); d={}
    for kv in f[1:]:
        k,v=kv.split('='); d[k]=float(v)
    INFO[f[0]]=d
STATS={}
for l in open(D+'stats.tsv'):
    f=l.rstrip('\n').split('\t'); d={}
    for kv in f[3:]:
        k,v=kv.split('=',1); d[k]=v
    STATS[(f[0],int(f[1]),f[2])]=d
STOCK=collections.defaultdict(dict)
for r in csv.DictReader(open(D+'stock.tsv'),delimiter='\t'):
    STOCK[(r['mesh'],int(r['qt']))][int(r['cl'])]=int(r['uv_bytes'])
RES={}
for r in csv.DictReader(open(D+'results.tsv'),delimiter='\t'):
    RES[(r['mesh'],int(r['qt']),r['order'],r['variant'])]=r
VARIANTS=[]
for k in RES:
    if k[3] not in VARIANTS: VARIANTS.append(k[3])
def uvv(name): return int(MAN[name]['uv_vertices'])
def kind(name): return MAN[name]['kind'].split(' ')[0]
def seam_bits(name): return INFO[name]['seam_bits_rans']
def stock_cl(name,qt):
    d=STOCK[(name,qt)]; return min(d,key=lambda c:(d[c],-c))
def stock_total_bits(name,qt): return 8*min(STOCK[(name,qt)].values())
def stock_value_bits(name,qt): return stock_total_bits(name,qt)-seam_bits(name)
# cost models: H<k> = order-0/context entropy + 16 bit/symbol/context tables; A<k> = adaptive coder estimate;
# R0 = raw order-0 entropy without tables; S = u,v separate (+tables); S1 = separate + ctx1
def cost(name,qt,order,var,model):
    r=RES[(name,qt,order,var)]; x=float(r['extra'])
    if model=='R0': return float(r['H0'])+x
    if model[0]=='H': k=model[1]; return float(r['H'+k])+float(r['T'+k])+x
    if model[0]=='A': return float(r[model])+x
    if model=='Zb': return min(cost(name,qt,order,var,'Z0'),cost(name,qt,order,var,'Z2'))
    if model[0]=='Z': k=model[1]; return float(r['Z'+k])+float(r['ZT'+k])+x
    if model=='S': return float(r['Hsep'])+float(r['Tsep'])+x
    if model=='S1': return float(r['H1sep'])+float(r['T1sep'])+x
    raise KeyError(model)
def bpv(name,qt,order,var,model): return cost(name,qt,order,var,model)/uvv(name)
REAL=[n for n in MAN if kind(n)!='synthetic-test']
def med(x): return statistics.median(x)
def mean(x): return sum(x)/len(x)
def gmean(x): return math.exp(sum(math.log(v) for v in x)/len(x))
