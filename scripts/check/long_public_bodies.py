# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Lists the function bodies of more than N lines (default 60) in the public
# headers (not internal/):  python3 scripts/check/long_public_bodies.py include/CGAL/Polyvector_fields [N]
import re,sys,os
# Reports function bodies longer than N lines in public headers (not internal/).
root=sys.argv[1]; N=int(sys.argv[2]) if len(sys.argv)>2 else 60
for dp,dn,fn in os.walk(root):
    if '/internal' in dp: continue
    for f in fn:
        if not f.endswith('.h'): continue
        p=os.path.join(dp,f); L=open(p).read().split('\n')
        i=0
        while i<len(L):
            line=L[i]
            # a body opening brace alone on a line, at indentation 0 or 2 (members)
            m=re.match(r'^( *)\{\s*$',line)
            if m and len(m.group(1)) in (0,2):
                ind=m.group(1); prev=L[i-1]
                if re.search(r'\)\s*(const)?\s*(noexcept)?\s*$',prev) or re.search(r'\)\s*:',prev) or prev.strip().startswith(':') or prev.strip().endswith(')'):
                    j=i+1
                    while j<len(L) and not re.match('^'+ind+r'\}',L[j]): j+=1
                    if j-i>N: print(f"{p}:{i+1}: {j-i} lines: {prev.strip()[:80]}")
                    i=j
            i+=1
