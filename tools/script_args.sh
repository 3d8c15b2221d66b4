# Sourced by the tools/*.sh scripts before they read their arguments:
#   check_script_args [ALLOWED_FLAG...] -- "$@"
# -h or --help prints the script's header comment (what it does, its usage) and exits 0; any other
# argument starting with '-' that is not allowed is refused, exit 2, instead of being taken for a
# directory to read or write ("--help/bin/lesson_09_psm_fixes not built").
check_script_args() {
  local allowed=() a f ok
  while [[ $# -gt 0 && $1 != -- ]]; do
    allowed+=("$1")
    shift
  done
  [[ $# -gt 0 ]] && shift
  for a in "$@"; do
    case $a in
      -h | --help)
        sed -n '2,/^[^#]/{/^#/{s/^# \{0,1\}//;p;};}' "$0"
        exit 0
        ;;
      -*)
        ok=0
        for f in "${allowed[@]}"; do [[ $a == "$f" ]] && ok=1; done
        if [[ $ok == 0 ]]; then
          local valid=""
          [[ ${#allowed[@]} -gt 0 ]] && valid="; valid: ${allowed[*]}"
          echo "$(basename "$0"): unknown flag '$a'$valid (--help: usage)" >&2
          exit 2
        fi
        ;;
    esac
  done
}
