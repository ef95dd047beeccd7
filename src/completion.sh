#!/bin/sh
# completion.sh PROGRAM: the completion of PROGRAM's command line for bash
# on the standard output, written from PROGRAM's own texts (paper/install.nw)
set -e
prog=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$prog" --help > "$tmp/main"
commands=$(awk '/^commands:$/ { on = 1; next } on && NF == 0 { exit } on { print $1 }' "$tmp/main")
for c in $commands; do "$prog" "$c" --help > "$tmp/$c"; done
"$prog" keys > "$tmp/keytable"
echo "# bash completion of contactopt: written by src/completion.sh from the"
echo "# texts of $("$prog" --version | sed -n 1p)"
echo "_contactopt_commands='$(echo $commands)'"
echo "_contactopt_options() {"
echo "  case \$1 in"
for c in $commands; do
  echo "    $c) echo '$(awk '/^  -/ { s = substr($0, 3); sub(/  .*/, "", s); gsub(/,/, "", s)
      n = split(s, w, " ")
      for (i = 1; i <= n; i++) if (w[i] ~ /^-/) printf "%s ", w[i] }' "$tmp/$c" |
    sed 's/ $//')' ;;"
done
echo "  esac; }"
echo "_contactopt_argument() {"
echo "  case \$1 in"
for c in $commands; do
  awk -v c=$c 'function kind(a) {
      return a ~ /^(DIR|SOLVEDIR)$/ ? "folder" : a ~ /^(FILE|NAME)$/ ? "file" :
             a ~ /=/ ? "key" : a == "SCENE" ? "scene" : "none" }
    NR == 1 && NF > 3 && $4 !~ /^\[/ { printf "    %s:) echo %s ;;\n", c, kind($4) }
    /^  -/ && match($0, /^  (-[^ ]+,? )*-[^ ]+( [A-Z]+| [^ ]*=[^ ]*)?( |$)/) {
      s = substr($0, 3, RLENGTH - 2); gsub(/,/, "", s); n = split(s, w, " ")
      if (n > 1 && w[n] !~ /^-/)
        for (i = 1; i < n; i++)
          if (w[i] ~ /^-/) printf "    %s:%s) echo %s ;;\n", c, w[i], kind(w[n]) }' "$tmp/$c"
done
echo "    *) echo none ;;"
echo "  esac; }"
echo "_contactopt_keys='$(awk -F '  +' 'NR > 1 { printf "%s%s", (NR > 2 ? " " : ""), $1 }' \
                         "$tmp/keytable")'"
echo "_contactopt_values() {"
echo "  case \$1 in"
awk -F '  +' 'NR > 1 && $4 ~ /^[a-z_0-9]+(, [a-z_0-9]+)+$/ {
    k = $1; sub(/[.]NAME[.]/, ".*.", k); v[$4] = v[$4] (v[$4] == "" ? "" : "|") k }
  END { for (a in v) { w = a; gsub(/,/, "", w); printf "    %s) echo %s ;;\n", v[a], w } }' \
  "$tmp/keytable" | sort
echo "  esac; }"
cat << 'EOF'
_contactopt() {
  local line=${COMP_LINE:0:COMP_POINT} cur prev cmd kind w n i
  cur=${line##*[[:space:]]}
  read -r -a w <<< "${line%"$cur"}"
  n=${#w[@]} prev=${w[n-1]} cmd=${w[1]}
  COMPREPLY=()
  if [ "$n" -le 1 ]; then
    COMPREPLY=($(compgen -W "$_contactopt_commands --help --version" -- "$cur"))
    return
  fi
  kind=$(_contactopt_argument "$cmd:$prev")
  if [ "$kind" = none ] && [ "$n" -eq 2 ] && [[ $cur != -* ]]; then
    kind=$(_contactopt_argument "$cmd:")
  fi
  if [ "$kind" = none ] && [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$(_contactopt_options "$cmd")" -- "$cur"))
    return
  fi
  case $kind in
    folder) COMPREPLY=($(compgen -d -- "$cur")) ;;
    file) COMPREPLY=($(compgen -f -- "$cur")) ;;
    scene) COMPREPLY=($(compgen -d -- "$cur") $(compgen -f -X '!*.scene' -- "$cur")) ;;
    key)
      if [[ $cur == *=* ]]; then
        COMPREPLY=($(compgen -P "${cur%%=*}=" -W "$(_contactopt_values "${cur%%=*}")" \
                             -- "${cur#*=}"))
      else
        COMPREPLY=($(compgen -S = -W "$_contactopt_keys" -- "$cur"))
        compopt -o nospace 2> /dev/null
      fi ;;
  esac
  if [[ $cur == *=* && $COMP_WORDBREAKS == *=* ]]; then
    for i in "${!COMPREPLY[@]}"; do COMPREPLY[i]=${COMPREPLY[i]#"${cur%=*}="}; done
  fi
}
complete -o filenames -F _contactopt contactopt
EOF
