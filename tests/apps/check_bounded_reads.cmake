cmake_minimum_required(VERSION 3.25)
# Every file reader refuses what is not a regular file, and a file over its size limit, before
# reading it (docs/architecture.md, "Files read"). Each case runs under a 1 GiB address-space
# cap and a 20 s timeout: without the checks, /dev/zero is read until memory runs out and a
# FIFO blocks for ever. Expects RECODE and DIR (a scratch folder).
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR}/dir.json)
file(CREATE_LINK /dev/zero ${DIR}/zero.json SYMBOLIC)
file(CREATE_LINK /dev/zero ${DIR}/zero.obj SYMBOLIC)
file(CREATE_LINK /dev/zero ${DIR}/zero.off SYMBOLIC)
execute_process(COMMAND mkfifo ${DIR}/fifo.json ${DIR}/fifo.obj RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mkfifo failed")
endif()
# Sparse files one byte over each limit: no disk space, no time to make.
execute_process(COMMAND truncate -s 67108865 ${DIR}/big.json)
execute_process(COMMAND truncate -s 1073741825 ${DIR}/big.obj)
foreach(mesh zero.obj zero.off fifo.obj big.obj)
  file(WRITE ${DIR}/scene-${mesh}.json
       "{\"objects\": [{\"mesh\": \"${mesh}\"}, {\"shape\": {\"type\": \"box\", \"size\": [1, 1, 1]}}]}\n")
endforeach()

set(not_regular "it is not a regular file")
set(cases
  "pair|/dev/zero|/dev/zero: cannot read scene file: ${not_regular} \\(a character device\\)"
  "pair|${DIR}/zero.json|zero.json: cannot read scene file: ${not_regular} \\(a character device\\)"
  "pair|${DIR}/fifo.json|fifo.json: cannot read scene file: ${not_regular} \\(a FIFO\\)"
  "run|${DIR}/dir.json|dir.json: cannot read scene file: it is a directory"
  "pair|${DIR}/big.json|big.json: cannot read scene file: it is 67108865 bytes \\(64.0 MiB\\), over the limit of 67108864 bytes \\(64 MiB\\) for a scene file"
  "replay|/dev/zero|/dev/zero: cannot read golden vector or command stream: ${not_regular}"
  "replay|${DIR}/fifo.json|fifo.json: cannot read golden vector or command stream: ${not_regular} \\(a FIFO\\)"
  "replay|${DIR}/big.json|big.json: cannot read golden vector or command stream: it is 67108865 bytes"
  "pair|${DIR}/scene-zero.obj.json|objects\\[0\\].mesh: .*zero.obj: cannot read mesh file: ${not_regular} \\(a character device\\)"
  "pair|${DIR}/scene-zero.off.json|objects\\[0\\].mesh: .*zero.off: cannot read mesh file: ${not_regular}"
  "pair|${DIR}/scene-fifo.obj.json|objects\\[0\\].mesh: .*fifo.obj: cannot read mesh file: ${not_regular} \\(a FIFO\\)"
  "pair|${DIR}/scene-big.obj.json|objects\\[0\\].mesh: .*big.obj: cannot read mesh file: it is 1073741825 bytes \\(1.0 GiB\\), over the limit of 1073741824 bytes \\(1 GiB\\) for a mesh file")
set(failed "")
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 command)
  list(GET parts 1 file)
  list(GET parts 2 expected)
  execute_process(COMMAND sh -c "ulimit -v 1048576; exec \"$0\" \"$1\" \"$2\"" ${RECODE} ${command} ${file}
                  TIMEOUT 20 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 1 AND err MATCHES "recode: error: .*${expected}")
    message(STATUS "ok: recode ${command} ${file}")
  else()
    string(APPEND failed "recode ${command} ${file}: status ${rc}, stderr:\n${err}\n  expected: ${expected}\n")
  endif()
endforeach()
file(REMOVE_RECURSE ${DIR})
if(failed)
  message(FATAL_ERROR "${failed}")
endif()
