# Shell helpers shared by the experiment scripts (source it after cd to the repository root).

# median: the median of the numbers on stdin, one per line (empty when there are none).
median() { sort -g | awk '{a[NR]=$1} END {if (NR == 0) print ""; else print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
