# A variant of a CONTACT input, for benches/peer/contact.sh and contact_eps.sh. Variables (each optional):
#   eps=E        tolerance EPS, with MAXGS = MAXIN = 9999 (CONTACT's largest)
#   dys=S        DY and FN times S (the same pressure on a strip S times as wide)
#   digits="O>2 A=1 W>5"   control digits of the X-H-G-I-A-O-W-R line: L>v raises digit L to at least v, L=v sets it
# Comment lines (starting with %) are left alone.
BEGIN {
  nr = split(digits, rules, " ")
  for (i = 1; i <= nr; i++) { op[substr(rules[i], 1, 1)] = substr(rules[i], 2, 1); val[substr(rules[i], 1, 1)] = substr(rules[i], 3, 1) }
}
$0 ~ /^[ \t]*%/ { print; next }
dys != "" && /MX,MY,XC1,YC1,DX,DY/ { $6 = $6 * dys }
dys != "" && /FN, (CKSI|FX)/ { $1 = sprintf("%.10g", $1 * dys) }
eps != "" && /MAXGS.*EPS/ {
  match($0, /^[ \t]*[^ \t]+[ \t]+[^ \t]+[ \t]+[^ \t]+[ \t]+[^ \t]+[ \t]+[^ \t]+/)
  $0 = sprintf("  9999  9999  %s  %s  %s", $3, $4, eps) substr($0, RSTART + RLENGTH)
}
nr > 0 && $2 ~ /G-I-A-O-W-R$/ {
  n = split($2, L, "-"); d = $1
  while (length(d) < n) d = "0" d
  out = ""
  for (i = 1; i <= n; i++) {
    c = substr(d, i, 1)
    if (op[L[i]] == ">" && c < val[L[i]]) c = val[L[i]]
    if (op[L[i]] == "=") c = val[L[i]]
    out = out c
  }
  match($0, /[0-9]+/)
  $0 = substr($0, 1, RSTART - 1) out substr($0, RSTART + RLENGTH)
}
{ print }
