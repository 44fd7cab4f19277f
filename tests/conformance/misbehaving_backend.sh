#!/bin/sh
# A back end that breaks the recode-conform-1 protocol in one way (the first argument), for the
# tests that `recode conform --exec` reports each clearly and exits within its timeout.
mode=$1
greet() {
  read -r _greeting
  printf '{"protocol":"recode-conform-1","name":"misbehaving: %s"}\n' "$mode"
}
case $mode in
  silent)        read -r _greeting; exec sleep 1000 ;;            # never greets
  hang)          greet; read -r _request; exec sleep 1000 ;;      # greets, never answers
  crash)         greet; read -r _request; kill -SEGV $$ ;;        # dies on the first request
  exit)          greet; read -r _request; exit 3 ;;
  garbage)       greet; read -r _request; echo 'hello, world' ;;  # not JSON
  flood)         greet; read -r _request; exec yes x ;;           # endless lines of "x"
  flood-line)    greet; read -r _request; yes | tr -d '\n' ;;     # one endless line
  stderr-flood)  greet; read -r _request; yes 'noise on stderr' >&2 ;;  # stderr only, no answer
  wrong-id)      greet; read -r _request; echo '{"id":99,"depth":[],"stencil":[]}'; exec sleep 1000 ;;
  short)         greet; read -r _request; echo '{"id":1,"depth":[1,2,3],"stencil":[0,0,0]}'; exec sleep 1000 ;;
  bad-greeting)  read -r _greeting; echo '{"protocol":"recode-conform-0","name":"old"}'; exec sleep 1000 ;;
  *) echo "misbehaving_backend.sh: unknown mode $mode" >&2; exit 1 ;;
esac
